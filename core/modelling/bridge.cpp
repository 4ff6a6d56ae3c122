#include "core/modelling/bridge.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <limits>
#include <numeric>
#include <unordered_map>

#include "core/modelling/delete_elements.h"
#include "core/modelling/mesh_queries.h"
#include "core/modelling/operation_words.h"
#include "core/support/error.h"

namespace gps {

namespace {

// A run of boundary vertices ordered along the faces' boundary edges (vertices[k] → vertices[k+1] is
// a face's edge); closed when it is a whole loop.
struct BoundaryRun {
  std::vector<int> vertices;
  bool closed = false;
};

// The boundary edges of the faces, a → b with no face on b → a: next[a] = b, previous[b] = a.
struct BoundaryEdges {
  std::vector<int> next, previous;
};

BoundaryEdges boundary_edges(const MeshArrays& a, const DirectedEdges& edges) {
  BoundaryEdges b{std::vector<int>(size_t(a.n_vertices()), -1), std::vector<int>(size_t(a.n_vertices()), -1)};
  for (const auto& face : a.faces)
    for (size_t k = 0; k < face.size(); ++k) {
      const int u = face[k], w = face[(k + 1) % face.size()];
      if (edges.count(directed_key(w, u)) == 0) {
        b.next[size_t(u)] = w;
        b.previous[size_t(w)] = u;
      }
    }
  return b;
}

// The selected vertices split into runs along the boundary edges joining them.
std::vector<BoundaryRun> boundary_runs(const BoundaryEdges& b, const std::vector<int>& selected) {
  std::unordered_map<int, bool> in;  // vertex → visited
  for (int v : selected) {
    if (b.next[size_t(v)] < 0) throw Error("vertex " + std::to_string(v) + " is not on a boundary");
    in[v] = false;
  }
  const auto selected_next = [&](int v, const std::vector<int>& step) {
    const int w = step[size_t(v)];
    return in.count(w) ? w : -1;
  };
  std::vector<BoundaryRun> runs;
  for (int v : selected) {
    if (in[v]) continue;
    int start = v;  // walk back to the run's first vertex (or once around a loop)
    while (selected_next(start, b.previous) >= 0 && selected_next(start, b.previous) != v)
      start = selected_next(start, b.previous);
    BoundaryRun run;
    for (int w = start; w >= 0 && !in[w]; w = selected_next(w, b.next)) {
      in[w] = true;
      run.vertices.push_back(w);
    }
    run.closed = run.vertices.size() >= 3 && selected_next(run.vertices.back(), b.next) == run.vertices.front();
    runs.push_back(std::move(run));
  }
  return runs;
}

// The one run the vertices make, refusing anything else.
BoundaryRun one_run(const BoundaryEdges& b, const std::vector<int>& vertices) {
  std::vector<BoundaryRun> runs = boundary_runs(b, vertices);
  if (runs.size() != 1)
    throw Error("vertex " + std::to_string(runs[1].vertices.front()) + " is not joined to vertex " +
                std::to_string(runs[0].vertices.front()) + " along the boundary: not one loop or chain");
  return runs.front();
}

// The band between runs p and q (p the longer, n ≥ m vertices): step i of p, from p[i] to p[i + 1],
// goes with q's vertices from partner(J(i)) to partner(J(i + 1)), J rising by 0 (a triangle) or 1 (a
// quad), partner(j) walking q against p's direction from its start s.
struct Band {
  size_t r = 0, s = 0;  // the phase of the triangles' spread and q's start (loops)
  size_t n = 0, m = 0;
  bool closed = false;

  size_t j_of(size_t i) const {
    if (closed) return (i * m + r) / n;
    return n == 1 ? 0 : (i * (m - 1) + (n - 1) / 2) / (n - 1);
  }
  size_t partner(size_t j) const { return closed ? (s + m - j % m) % m : m - 1 - j; }
};

// Twice the area vector of a face (Newell's sums).
Vec3 area_vector(const MeshArrays& a, const std::vector<int>& face) {
  Vec3 sum = Vec3::Zero();
  for (size_t k = 0; k < face.size(); ++k)
    sum += a.means[size_t(face[k])].cross(a.means[size_t(face[(k + 1) % face.size()])]);
  return sum;
}

// A list of vertices as messages name them ("1, 2, 5"), by their input indices.
std::string vertex_list(const std::vector<int>& face, const std::vector<int>& input_index) {
  std::string out;
  for (int v : face) out += (out.empty() ? "" : ", ") + std::to_string(input_index[size_t(v)]);
  return out;
}

// Bridges two runs of `arrays` (made from `mesh`); `input_index` names its vertices in messages (their indices in the
// mesh the caller was given).
Modelled bridge_runs(const CovarianceMesh& mesh, MeshArrays a, const BoundaryRun& first, const BoundaryRun& second,
                     const std::vector<int>& input_index, const std::string& done_before) {
  if (first.closed != second.closed) throw Error("cannot bridge a closed boundary loop to an open chain");
  if (first.vertices.size() < 2 || second.vertices.size() < 2)
    throw Error("a chain to bridge needs at least 2 vertices");
  const bool swap = first.vertices.size() < second.vertices.size();
  const std::vector<int>& p = swap ? second.vertices : first.vertices;
  const std::vector<int>& q = swap ? first.vertices : second.vertices;
  Band band{0, 0, p.size(), q.size(), first.closed};
  const size_t n = band.n, m = band.m;
  if (band.closed) {
    // Every start of q and spread of the triangles; the band's edges between the loops are p[i]–partner(J(i)).
    std::vector<double> distance(n * m);
    for (size_t i = 0; i < n; ++i)
      for (size_t j = 0; j < m; ++j) distance[i * m + j] = (a.means[size_t(p[i])] - a.means[size_t(q[j])]).norm();
    double best = std::numeric_limits<double>::infinity();
    Band trial = band;
    for (trial.r = 0; trial.r < (n == m ? 1 : n); ++trial.r)
      for (trial.s = 0; trial.s < m; ++trial.s) {
        double length = 0;
        for (size_t i = 0; i < n; ++i) length += distance[i * m + trial.partner(trial.j_of(i))];
        if (length < best) best = length, band = trial;
      }
  }
  const bool triangles = all_triangles(a);
  const DirectedEdges existing = directed_edges(a);
  const size_t first_new = a.faces.size(), steps = band.closed ? n : n - 1;
  for (size_t i = 0; i < steps; ++i) {
    const size_t j0 = band.j_of(i), j1 = band.j_of(i + 1);
    std::vector<int> face = {p[(i + 1) % n], p[i], q[band.partner(j0)]};
    if (j1 != j0) face.push_back(q[band.partner(j1)]);
    for (size_t k = 0; k < face.size(); ++k) {
      const int u = face[k], v = face[(k + 1) % face.size()];
      if (existing.count(directed_key(u, v)))
        throw Error(edge_name(input_index[size_t(u)], input_index[size_t(v)]) +
                    " already joins the loops: the bridge would give it a third face");
    }
    a.faces.push_back(std::move(face));
  }
  if (triangles) {
    for (size_t f = first_new; f < a.faces.size(); ++f) {
      std::vector<int>& face = a.faces[f];  // the shorter diagonal from the first corner
      const auto length = [&](int u, int v) { return (a.means[size_t(u)] - a.means[size_t(v)]).squaredNorm(); };
      if (face.size() == 4 && length(face[1], face[3]) < length(face[0], face[2]))
        std::rotate(face.begin(), face.begin() + 1, face.end());
    }
    split_new_quads(a, int(first_new));
  }
  // A face of no area: relative to the loops' size, as far as rounding can tell.
  Vec3 lo = a.means[size_t(p[0])], hi = lo;
  for (const std::vector<int>* run : {&p, &q})
    for (int v : *run) lo = lo.cwiseMin(a.means[size_t(v)]), hi = hi.cwiseMax(a.means[size_t(v)]);
  const double size = (hi - lo).norm();
  for (size_t f = first_new; f < a.faces.size(); ++f)
    if (!(area_vector(a, a.faces[f]).norm() > 1e-12 * size * size))
      throw Error("the bridge's face through vertices " + vertex_list(a.faces[f], input_index) +
                  " would have no area (the loops coincide or line up there)");
  std::vector<int> selection = p;
  selection.insert(selection.end(), q.begin(), q.end());
  std::sort(selection.begin(), selection.end());
  const std::string lengths =
      n == m ? count_of(n, "vertex", "vertices")
             : std::to_string(first.vertices.size()) + " and " + count_of(second.vertices.size(), "vertex", "vertices");
  const size_t added = a.faces.size() - first_new;
  return modelled(mesh, std::move(a), selection,
                  done_before + "bridged two " + std::string(band.closed ? "loops" : "chains") + " of " + lengths +
                      ": " + count_of(added, "face", "faces") + " added" +
                      (n == m ? "" : " (" + count_of(n - m, "triangle", "triangles") + " spreading the difference)"));
}

std::vector<int> identity_index(int n) {
  std::vector<int> out(static_cast<size_t>(n));
  std::iota(out.begin(), out.end(), 0);
  return out;
}

}  // namespace

Modelled bridge(const CovarianceMesh& mesh, const std::vector<int>& loop_a, const std::vector<int>& loop_b) {
  const MeshArrays a = arrays_of(mesh);
  const std::vector<int> sa = sorted_vertices(a, loop_a), sb = sorted_vertices(a, loop_b);
  for (const std::vector<int>* loop : {&loop_a, &loop_b}) {
    std::vector<int> listed = *loop;
    std::sort(listed.begin(), listed.end());
    if (const auto twice = std::adjacent_find(listed.begin(), listed.end()); twice != listed.end())
      throw Error("vertex " + std::to_string(*twice) + " is listed twice in a loop");
  }
  for (int v : sa)
    if (std::binary_search(sb.begin(), sb.end(), v)) throw Error("vertex " + std::to_string(v) + " is in both loops");
  if (sa.size() < 2 || sb.size() < 2) throw Error("a chain to bridge needs at least 2 vertices");
  const BoundaryEdges b = boundary_edges(a, directed_edges(a));
  return bridge_runs(mesh, a, one_run(b, sa), one_run(b, sb), identity_index(a.n_vertices()), "");
}

namespace {

// Two face regions whose borders are loops of the mesh's boundary: the loops bridged, then the regions'
// faces deleted (and the vertices only they used), the selection and origins followed through both.
Modelled bridged_then_deleted(const CovarianceMesh& mesh, const std::array<std::vector<int>, 2>& border,
                              const std::vector<int>& chosen) {
  const Modelled bridged = bridge(mesh, border[0], border[1]);
  Modelled out = with_faces_deleted(bridged, chosen);
  out.summary = "deleted " + count_of(chosen.size(), "face", "faces") + ", " + bridged.summary;
  return out;
}

}  // namespace

Modelled bridge_faces(const CovarianceMesh& mesh, const std::vector<int>& faces) {
  MeshArrays a = arrays_of(mesh);
  const std::vector<int> chosen = sorted_faces(a, faces);
  // The regions: chosen faces joined through shared edges (union-find).
  std::vector<int> parent(chosen.size());
  for (size_t i = 0; i < parent.size(); ++i) parent[i] = int(i);
  const auto root = [&](int i) {
    while (parent[size_t(i)] != i) i = parent[size_t(i)] = parent[size_t(parent[size_t(i)])];
    return i;
  };
  std::unordered_map<uint64_t, int> chosen_of_edge;  // directed edge → index in `chosen`
  for (size_t i = 0; i < chosen.size(); ++i) {
    const std::vector<int>& face = a.faces[size_t(chosen[i])];
    for (size_t k = 0; k < face.size(); ++k)
      chosen_of_edge[directed_key(face[k], face[(k + 1) % face.size()])] = int(i);
  }
  for (const auto& [key, i] : chosen_of_edge)
    if (const auto twin = chosen_of_edge.find((key << 32) | (key >> 32)); twin != chosen_of_edge.end())
      parent[size_t(root(i))] = root(twin->second);
  std::vector<int> region_roots;
  for (size_t i = 0; i < chosen.size(); ++i)
    if (root(int(i)) == int(i)) region_roots.push_back(int(i));
  if (region_roots.size() != 2)
    throw Error("the faces make " + count_of(region_roots.size(), "region", "regions") +
                " (faces joined by edges); bridge needs exactly 2");
  // Each region's border: its edges whose other side is a face not chosen.
  const DirectedEdges edges(mesh);
  std::array<std::vector<int>, 2> border;
  std::vector<int> region_of_vertex(size_t(a.n_vertices()), -1);
  // Per region: a face of it with a border edge on the mesh's boundary and one with a border edge
  // inside the mesh (−1: none); a region's border must be all of one kind.
  std::array<int, 2> on_boundary{-1, -1}, inside{-1, -1};
  std::array<std::array<int, 2>, 2> boundary_edge{};
  for (size_t i = 0; i < chosen.size(); ++i) {
    const std::vector<int>& corners = a.faces[size_t(chosen[i])];
    const int region = root(int(i)) == region_roots[0] ? 0 : 1;
    for (size_t k = 0; k < corners.size(); ++k) {
      const int u = corners[k], v = corners[(k + 1) % corners.size()];
      if (chosen_of_edge.count(directed_key(v, u))) continue;
      if (edges.count(directed_key(v, u))) {
        inside[size_t(region)] = chosen[i];
      } else if (on_boundary[size_t(region)] < 0) {  // the first, for the message
        on_boundary[size_t(region)] = chosen[i];
        boundary_edge[size_t(region)] = {u, v};
      }
      for (int w : {u, v}) {
        if (region_of_vertex[size_t(w)] == 1 - region)
          throw Error("the regions of faces " + std::to_string(chosen[size_t(region_roots[0])]) + " and " +
                      std::to_string(chosen[size_t(region_roots[1])]) + " touch at vertex " + std::to_string(w));
        if (region_of_vertex[size_t(w)] < 0) border[size_t(region)].push_back(w);
        region_of_vertex[size_t(w)] = region;
      }
    }
  }
  for (size_t r = 0; r < 2; ++r)
    if (on_boundary[r] >= 0 && (inside[r] >= 0 || inside[1 - r] >= 0))
      throw Error("the region of face " + std::to_string(on_boundary[r]) + " reaches the mesh's boundary at " +
                  edge_name(boundary_edge[r][0], boundary_edge[r][1]) +
                  (inside[r] >= 0 ? " and meets other faces too" : " and the other region does not") +
                  ": their borders cannot both be bridged");
  // Regions whose borders are the mesh's boundary (faces apart, or the caps of an open shell): as
  // Blender, their borders are bridged and then they go, leaving the band.
  if (on_boundary[0] >= 0) return bridged_then_deleted(mesh, border, chosen);
  std::vector<char> deleted(size_t(a.n_faces()), 0);
  for (int f : chosen) deleted[size_t(f)] = 1;
  remove_faces(a, deleted);
  const std::vector<int> new_index = drop_unused_vertices(a);
  std::vector<int> input_index(static_cast<size_t>(a.n_vertices()));
  for (size_t v = 0; v < new_index.size(); ++v)
    if (new_index[v] >= 0) input_index[size_t(new_index[v])] = int(v);
  const BoundaryEdges b = boundary_edges(a, directed_edges(a));
  std::array<BoundaryRun, 2> runs;
  for (size_t r = 0; r < 2; ++r) {
    std::vector<int> loop;
    for (int v : border[r]) loop.push_back(new_index[size_t(v)]);
    std::sort(loop.begin(), loop.end());
    const std::vector<BoundaryRun> found = boundary_runs(b, loop);
    if (found.size() != 1 || !found[0].closed)
      throw Error("the border of the region of face " + std::to_string(chosen[size_t(region_roots[r])]) +
                  " is not one loop: bridge needs one each");
    runs[r] = found[0];
  }
  return bridge_runs(mesh, a, runs[0], runs[1], input_index,
                     "deleted " + count_of(chosen.size(), "face", "faces") + ", ");
}

Modelled bridge_selected(const CovarianceMesh& mesh, const std::vector<int>& vertices) {
  const MeshArrays a = arrays_of(mesh);
  const BoundaryEdges b = boundary_edges(a, directed_edges(a));
  const std::vector<int> selected = sorted_vertices(a, vertices);
  if (std::any_of(selected.begin(), selected.end(), [&](int v) { return b.next[size_t(v)] < 0; })) {
    const std::vector<int> faces = faces_within(mesh, selected);
    if (faces.empty()) {
      const int off = *std::find_if(selected.begin(), selected.end(), [&](int v) { return b.next[size_t(v)] < 0; });
      throw Error("vertex " + std::to_string(off) + " is not on a boundary, and the selection holds no face to bridge");
    }
    return bridge_faces(mesh, faces);
  }
  const std::vector<BoundaryRun> runs = boundary_runs(b, selected);
  if (runs.size() != 2)
    throw Error("the selection makes " + std::to_string(runs.size()) +
                " boundary loops or chains; bridge needs exactly 2");
  return bridge_runs(mesh, a, runs[0], runs[1], identity_index(a.n_vertices()), "");
}

}  // namespace gps
