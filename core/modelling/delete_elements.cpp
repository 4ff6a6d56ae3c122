#include "core/modelling/delete_elements.h"

#include <algorithm>
#include <set>
#include <string>
#include <unordered_map>

#include "core/support/error.h"
#include "core/modelling/operation_words.h"

namespace gps {

namespace {

/// "<head>: F faces, V vertices removed" (the faces left out when `count_faces` is false, the
/// vertices when none were removed).
std::string summary(const std::string& head, size_t faces_removed, size_t vertices_removed, bool count_faces) {
  std::vector<std::string> parts;
  if (count_faces) parts.push_back(count_of(faces_removed, "face", "faces"));
  if (vertices_removed > 0) parts.push_back(count_of(vertices_removed, "vertex", "vertices"));
  std::string s = head;
  for (size_t i = 0; i < parts.size(); ++i) s += (i == 0 ? ": " : ", ") + parts[i];
  return parts.empty() ? s : s + " removed";
}

/// Removes from `a` the faces marked in `removed` and the vertices left unused; returns the summary.
/// Refuses an empty result and a vertex at which the remaining faces would form more than one fan, so
/// that what it leaves is a mesh build_mesh takes.
std::string without_faces(MeshArrays& a, const std::vector<char>& removed, const std::string& head, bool count_faces) {
  std::vector<char> touched(size_t(a.n_vertices()), 0);
  size_t faces_removed = 0;
  for (int f = 0; f < a.n_faces(); ++f) {
    if (!removed[size_t(f)]) continue;
    ++faces_removed;
    for (int v : a.faces[size_t(f)]) touched[size_t(v)] = 1;
  }
  if (faces_removed == a.faces.size()) throw Error("the result would have no faces");
  remove_faces(a, removed);

  // Around a vertex that lost a face the remaining faces form open fans: one per corner there that
  // has no face across its outgoing edge. More than one fan makes the vertex non-manifold.
  // Only the faces at such a vertex are looked up: the face across an edge out of it has it too. The
  // same pass flags the vertices the remaining faces use, for drop_unused_vertices.
  DirectedEdges edges;
  std::vector<int> near;  // the faces at such a vertex
  std::vector<char> used(size_t(a.n_vertices()), 0);
  for (int f = 0; f < a.n_faces(); ++f) {
    const auto& face = a.faces[size_t(f)];
    bool at_touched = false;
    for (const int v : face) {
      used[size_t(v)] = 1;
      at_touched = at_touched || touched[size_t(v)] != 0;
    }
    if (!at_touched) continue;
    near.push_back(f);
    for (size_t k = 0; k < face.size(); ++k)
      edges.emplace(directed_key(face[k], face[(k + 1) % face.size()]), std::pair<int, int>(f, int(k)));
  }
  std::vector<int> fans(size_t(a.n_vertices()), 0);
  for (const int f : near) {
    const auto& face = a.faces[size_t(f)];
    for (size_t k = 0; k < face.size(); ++k) {
      const int v = face[k], w = face[(k + 1) % face.size()];
      if (touched[size_t(v)] && !edges.count(directed_key(w, v))) ++fans[size_t(v)];
    }
  }
  for (int v = 0; v < a.n_vertices(); ++v)
    if (fans[size_t(v)] > 1)
      throw Error("the result would be non-manifold at vertex " + std::to_string(v) + " (" +
                  std::to_string(fans[size_t(v)]) + " fans of faces would meet only there)");

  const int n_vertices = a.n_vertices();
  drop_unused_vertices(a, used);
  return summary(head, faces_removed, size_t(n_vertices - a.n_vertices()), count_faces);
}

/// Checks the edges (in the mesh; interior when `interior`) and returns them once each.
std::vector<std::array<int, 2>> checked_edges(const DirectedEdges& de, const std::vector<std::array<int, 2>>& edges,
                                              bool interior) {
  if (edges.empty()) throw Error("no edges are selected");
  std::vector<std::array<int, 2>> unique;
  std::set<uint64_t> seen;
  for (const auto& [x, y] : edges) {
    if (!has_edge(de, x, y)) throw Error(edge_name(x, y) + " is not in the mesh");
    if (interior && is_boundary_edge(de, x, y)) throw Error(edge_name(x, y) + " is on the boundary");
    if (seen.insert(edge_key(x, y)).second) unique.push_back({x, y});
  }
  return unique;
}

/// Faces being merged across edges, in arrays made from `mesh` (arrays_of, unchanged when the merger is
/// made). Each directed edge knows its current face: the mesh's, where no merge changed it. A merged
/// polygon keeps the lower face index and the corner order of that face.
class FaceMerger {
public:
  FaceMerger(MeshArrays& a, const CovarianceMesh& mesh)
      : a_(a), mesh_edges_(mesh), alive_(size_t(a.n_faces()), 1), merged_into_(size_t(a.n_faces()), -1) {}

  bool has(int x, int y) const { return face_of(x, y) >= 0; }

  /// Removes the interior edge {p, q}, merging the faces on its two sides (`what` names the element
  /// being dissolved, for errors).
  void dissolve(int p, int q, const std::string& what) {
    const int f = face_of(p, q), g = face_of(q, p);
    if (f < 0 || g < 0) throw Error("dissolving " + what + " would open the mesh at " + edge_name(p, q));
    if (f == g) {
      remove_spike(f, p, q, what);
    } else {
      const int keep = std::min(f, g), other = std::max(f, g);
      const int x = keep == f ? p : q, y = keep == f ? q : p;  // keep has x → y, other has y → x
      const std::vector<int>& k_face = a_.faces[size_t(keep)];
      const std::vector<int>& o_face = a_.faces[size_t(other)];
      const size_t i = corner_of(k_face, x, y), j = corner_of(o_face, y, x), n = o_face.size();
      std::vector<int> merged(k_face.begin(), k_face.begin() + long(i) + 1);
      for (size_t step = 2; step < n; ++step) merged.push_back(o_face[(j + step) % n]);
      merged.insert(merged.end(), k_face.begin() + long(i) + 1, k_face.end());
      for (size_t c = 0; c < n; ++c) changed_[directed_key(o_face[c], o_face[(c + 1) % n])] = keep;
      a_.faces[size_t(keep)] = std::move(merged);
      a_.faces[size_t(other)].clear();
      alive_[size_t(other)] = 0;
      merged_into_[size_t(other)] = keep;
      touched_.push_back(keep);
    }
    changed_[directed_key(p, q)] = -1;
    changed_[directed_key(q, p)] = -1;
    touched_.push_back(f);
  }

  /// Removes the vertex v from the face that input face `f` is now part of: its edges u → v → w
  /// become u → w.
  void remove_from_face(int v, int f) {
    f = now(f);
    std::vector<int>& face = a_.faces[size_t(f)];
    const size_t c = size_t(std::find(face.begin(), face.end(), v) - face.begin()), n = face.size();
    const int u = face[(c + n - 1) % n], w = face[(c + 1) % n];
    face.erase(face.begin() + long(c));
    changed_[directed_key(u, v)] = -1;
    changed_[directed_key(v, w)] = -1;
    changed_[directed_key(u, w)] = f;
    touched_.push_back(f);
  }

  /// The face input face `f` is now part of.
  int now(int f) const {
    while (!alive_[size_t(f)]) f = merged_into_[size_t(f)];
    return f;
  }

  /// Where vertex v, whose input faces are `faces`, now lies in exactly two faces, once in each, between
  /// the same two neighbours (two edges in a line, as a loop cut's vertex is once the edges along the
  /// loop are gone): removes it from both, joining its two edges. False, changing nothing, otherwise.
  bool join_edges_at(int v, std::span<const int> faces) {
    std::vector<int> now_in;
    for (const int f : faces)
      if (const int g = now(f); std::find(now_in.begin(), now_in.end(), g) == now_in.end()) now_in.push_back(g);
    if (now_in.size() != 2) return false;
    std::array<std::array<int, 2>, 2> sides{};  // per face: the corners before and after v
    for (size_t i = 0; i < 2; ++i) {
      const std::vector<int>& face = a_.faces[size_t(now_in[i])];
      if (std::count(face.begin(), face.end(), v) != 1) return false;
      const size_t c = size_t(std::find(face.begin(), face.end(), v) - face.begin()), n = face.size();
      sides[i] = {face[(c + n - 1) % n], face[(c + 1) % n]};
    }
    if (sides[0][0] != sides[1][1] || sides[0][1] != sides[1][0]) return false;
    remove_from_face(v, now_in[0]);
    remove_from_face(v, now_in[1]);
    return true;
  }

  /// Refuses a face left with fewer than 3 corners or a vertex twice (only a face changed can be); then
  /// drops the merged-away faces.
  void finish() {
    std::sort(touched_.begin(), touched_.end());
    touched_.erase(std::unique(touched_.begin(), touched_.end()), touched_.end());
    for (const int f : touched_) {
      if (!alive_[size_t(f)]) continue;
      std::vector<int> corners = a_.faces[size_t(f)];
      if (corners.size() < 3)
        throw Error("face " + std::to_string(f) + " would be left with " + std::to_string(corners.size()) + " corners");
      std::sort(corners.begin(), corners.end());
      const auto twice = std::adjacent_find(corners.begin(), corners.end());
      if (twice != corners.end())
        throw Error("the merged face " + std::to_string(f) + " would have vertex " + std::to_string(*twice) + " twice");
    }
    std::vector<char> dead(alive_.size());
    for (size_t f = 0; f < alive_.size(); ++f) dead[f] = !alive_[f];
    remove_faces(a_, dead);
  }

private:
  static size_t corner_of(const std::vector<int>& face, int x, int y) {
    for (size_t k = 0; k < face.size(); ++k)
      if (face[k] == x && face[(k + 1) % face.size()] == y) return k;
    return face.size();
  }

  /// Both sides of {p, q} are one face: allowed only where the edge is a spike p → q → p (or
  /// q → p → q), whose tip and one repeat of its base go.
  void remove_spike(int f, int p, int q, const std::string& what) {
    std::vector<int>& face = a_.faces[size_t(f)];
    const size_t n = face.size(), i = corner_of(face, p, q), j = corner_of(face, q, p);
    size_t tip;
    if (j == (i + 1) % n)
      tip = j;
    else if (i == (j + 1) % n)
      tip = i;
    else
      throw Error("dissolving " + what + " would cut a hole into face " + std::to_string(f));
    const size_t repeat = (tip + 1) % n;
    face.erase(face.begin() + long(std::max(tip, repeat)));
    face.erase(face.begin() + long(std::min(tip, repeat)));
  }

  /// The face that now runs x → y, or −1.
  int face_of(int x, int y) const {
    const uint64_t key = directed_key(x, y);
    if (const auto it = changed_.find(key); it != changed_.end()) return it->second;
    return mesh_edges_.place(key).first;
  }

  MeshArrays& a_;
  const DirectedEdges mesh_edges_;  ///< the mesh's, before any merge
  std::vector<char> alive_;
  std::vector<int> merged_into_;  ///< by merged-away face: the face it went into
  std::unordered_map<uint64_t, int> changed_;  ///< directed edges whose face a merge changed (−1: gone)
  std::vector<int> touched_;                   ///< faces a merge changed
};

Modelled merged(const CovarianceMesh& mesh, MeshArrays& a, FaceMerger& merger, const std::string& head) {
  const int n_faces = a.n_faces(), n_vertices = a.n_vertices();
  merger.finish();
  drop_unused_vertices(a);
  Modelled out;
  out.mesh = build_mesh(a, mesh);
  out.vertex_origin = vertex_origin(a);
  out.summary = summary(head, size_t(n_faces - a.n_faces()), size_t(n_vertices - a.n_vertices()), true);
  return out;
}

}  // namespace

std::vector<int> delete_faces_in(MeshArrays& a, const std::vector<int>& faces, std::string& summary) {
  if (faces.empty()) throw Error("no faces are selected");
  const std::vector<int> chosen = sorted_faces(a, faces);
  std::vector<char> removed(size_t(a.n_faces()), 0);
  for (int f : chosen) removed[size_t(f)] = 1;
  summary = without_faces(a, removed, "deleted " + count_of(chosen.size(), "face", "faces"), false);
  return {};
}

std::vector<int> delete_vertices_in(MeshArrays& a, const std::vector<int>& vertices, std::string& summary) {
  if (vertices.empty()) throw Error("no vertices are selected");
  const std::vector<int> chosen = sorted_vertices(a, vertices);
  std::vector<char> selected(size_t(a.n_vertices()), 0);
  for (int v : chosen) selected[size_t(v)] = 1;
  std::vector<char> removed(size_t(a.n_faces()), 0);
  for (int f = 0; f < a.n_faces(); ++f)
    for (int v : a.faces[size_t(f)]) removed[size_t(f)] |= selected[size_t(v)];
  summary = without_faces(a, removed, "deleted " + count_of(chosen.size(), "vertex", "vertices"), true);
  return {};
}

namespace {

// delete_edges_in with the arrays' directed edges `de`.
std::vector<int> delete_edges_with(MeshArrays& a, const DirectedEdges& de, const std::vector<std::array<int, 2>>& edges,
                                   std::string& summary) {
  const std::vector<std::array<int, 2>> chosen = checked_edges(de, edges, false);
  std::vector<char> removed(size_t(a.n_faces()), 0);
  for (const auto& [x, y] : chosen)
    for (const uint64_t key : {directed_key(x, y), directed_key(y, x)})
      if (const int f = de.place(key).first; f >= 0) removed[size_t(f)] = 1;
  summary = without_faces(a, removed, "deleted " + count_of(chosen.size(), "edge", "edges"), true);
  return {};
}

}  // namespace

std::vector<int> delete_edges_in(MeshArrays& a, const std::vector<std::array<int, 2>>& edges, std::string& summary) {
  return delete_edges_with(a, directed_edges(a), edges, summary);
}

Modelled delete_faces(const CovarianceMesh& mesh, const std::vector<int>& faces) {
  return modelled_by(mesh, [&](MeshArrays& a, std::string& summary) { return delete_faces_in(a, faces, summary); });
}

Modelled with_faces_deleted(const Modelled& result, const std::vector<int>& faces) {
  Modelled out = delete_faces(result.mesh, faces);
  std::vector<int> selection, origin;
  const bool known =
      out.vertex_origin.size() == out.mesh.n_vertices() && result.vertex_origin.size() == result.mesh.n_vertices();
  for (size_t w = 0; w < out.mesh.n_vertices(); ++w) {
    const int made = out.vertex_origin.empty() ? int(w) : out.vertex_origin[w];
    if (std::binary_search(result.selection.begin(), result.selection.end(), made)) selection.push_back(int(w));
    if (known) origin.push_back(made < 0 ? -1 : result.vertex_origin[size_t(made)]);
  }
  out.selection = std::move(selection);
  out.vertex_origin = std::move(origin);
  out.summary = result.summary;
  return out;
}

Modelled delete_vertices(const CovarianceMesh& mesh, const std::vector<int>& vertices) {
  return modelled_by(mesh,
                     [&](MeshArrays& a, std::string& summary) { return delete_vertices_in(a, vertices, summary); });
}

Modelled delete_edges(const CovarianceMesh& mesh, const std::vector<std::array<int, 2>>& edges) {
  return modelled_by(mesh, [&](MeshArrays& a, std::string& summary) {
    return delete_edges_with(a, DirectedEdges(mesh), edges, summary);
  });
}

Modelled dissolve_vertices(const CovarianceMesh& mesh, const std::vector<int>& vertices) {
  MeshArrays a = arrays_of(mesh);
  if (vertices.empty()) throw Error("no vertices are selected");
  const std::vector<int> chosen = sorted_vertices(a, vertices);
  // Per chosen vertex: the vertices after it in its faces, its faces (in face order) and its last
  // face, from the mesh's rows.
  const PolygonTopology& t = mesh.topology();
  const MeshConnectivity& c = mesh.connectivity();
  std::vector<std::vector<int>> next(size_t(a.n_vertices())), faces_of(size_t(a.n_vertices()));
  std::vector<int> face_of_vertex(size_t(a.n_vertices()), -1);
  std::vector<char> on_boundary(size_t(a.n_vertices()), 0);
  for (const int v : chosen) {
    for (int i = c.vertex_face_offsets[size_t(v)]; i < c.vertex_face_offsets[size_t(v) + 1]; ++i) {
      const int f = c.vertex_faces[size_t(i)], k = c.vertex_face_corners[size_t(i)];
      next[size_t(v)].push_back(t.verts[size_t(t.offsets[size_t(f)] + (k + 1) % t.face_size(f))]);
      faces_of[size_t(v)].push_back(f);
      face_of_vertex[size_t(v)] = f;
    }
    on_boundary[size_t(v)] = mesh.is_boundary_vertex(size_t(v));
  }
  for (int v : chosen)
    if (on_boundary[size_t(v)] && next[size_t(v)].size() != 1)
      throw Error("vertex " + std::to_string(v) + " is on the boundary of " +
                  count_of(next[size_t(v)].size(), "face", "faces") +
                  " (only a boundary vertex of a single face can be dissolved)");

  FaceMerger merger(a, mesh);
  // As Blender dissolves them: first the edges between two of the interior vertices, then each vertex
  // left between two edges in a line joins them, and the faces around any other merge into one. So the
  // vertices of a loop cut give back the faces it cut.
  std::vector<char> interior_chosen(size_t(a.n_vertices()), 0);
  for (int v : chosen) interior_chosen[size_t(v)] = !on_boundary[size_t(v)];
  for (int v : chosen)
    for (int w : next[size_t(v)])
      if (interior_chosen[size_t(v)] && interior_chosen[size_t(w)] && merger.has(v, w))
        merger.dissolve(v, w, "vertex " + std::to_string(v));
  for (int v : chosen) {
    const std::string what = "vertex " + std::to_string(v);
    if (on_boundary[size_t(v)]) {
      merger.remove_from_face(v, face_of_vertex[size_t(v)]);
      continue;
    }
    if (merger.join_edges_at(v, faces_of[size_t(v)])) continue;
    for (int w : next[size_t(v)])
      if (merger.has(v, w)) merger.dissolve(v, w, what);
  }
  return merged(mesh, a, merger, "dissolved " + count_of(chosen.size(), "vertex", "vertices"));
}

Modelled dissolve_edges(const CovarianceMesh& mesh, const std::vector<std::array<int, 2>>& edges) {
  MeshArrays a = arrays_of(mesh);
  const std::vector<std::array<int, 2>> chosen = checked_edges(DirectedEdges(mesh), edges, true);
  // The edges' ends, with their faces in face order, for the ends left between two edges in a line.
  const MeshConnectivity& c = mesh.connectivity();
  std::vector<int> ends;
  for (const auto& [x, y] : chosen) ends.insert(ends.end(), {x, y});
  std::sort(ends.begin(), ends.end());
  ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
  FaceMerger merger(a, mesh);
  for (const auto& [x, y] : chosen) merger.dissolve(x, y, edge_name(x, y));
  // As Blender's Dissolve Edges (its Dissolve Vertices on): an end left between two edges in a line
  // joins them, so that dissolving a loop cut's edges gives back the faces it cut.
  for (const int v : ends) merger.join_edges_at(v, c.faces_of_vertex(v));
  return merged(mesh, a, merger, "dissolved " + count_of(chosen.size(), "edge", "edges"));
}

}  // namespace gps
