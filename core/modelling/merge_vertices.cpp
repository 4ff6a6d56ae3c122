#include "core/modelling/merge_vertices.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <set>
#include <sstream>
#include <unordered_map>

#include "core/support/error.h"

namespace gps {

namespace {

// The Gaussian a group merges into at its centre: the mean of the means, the covariance of the 9D average.
Gaussian group_center(const MeshArrays& a, const std::vector<int>& group) {
  std::vector<std::pair<int, double>> weights;
  Vec3 mean = Vec3::Zero();
  for (int v : group) {
    weights.emplace_back(v, 1.0 / double(group.size()));
    mean += a.means[size_t(v)];
  }
  return {mean / double(group.size()), blend_gaussians(a, weights).covariance};
}

struct MergeResult {
  MeshArrays arrays;
  std::vector<int> new_index;  // old vertex → new (−1 deleted)
  int faces_removed = 0;
};

// The faces face `f` (its corners replaced by their targets) becomes: the face itself, or where a
// vertex it now meets twice pinches it into loops (two opposite corners of a quad merged: two
// slivers of two corners), each loop of 3 or more corners, as Blender splits it; none where no loop
// is left. `last_seen`: per vertex, the last face whose walk met it. `whole`: the face was one loop.
std::vector<std::vector<int>> merged_face(const std::vector<int>& corners, const std::vector<int>& target, int f,
                                          std::vector<int>& last_seen, bool& whole) {
  std::vector<int> face;
  for (int v : corners) {
    const int t = target[size_t(v)];
    if (face.empty() || face.back() != t) face.push_back(t);
  }
  while (face.size() > 1 && face.front() == face.back()) face.pop_back();
  // Walked as a stack: a vertex met again closes the loop since its last visit.
  std::vector<std::vector<int>> loops;
  std::vector<int> stack;
  for (const int v : face) {
    if (last_seen[size_t(v)] == f) {
      const auto at = std::find(stack.begin(), stack.end(), v);
      loops.emplace_back(at, stack.end());
      for (auto closed = at + 1; closed != stack.end(); ++closed) last_seen[size_t(*closed)] = -1;  // may recur
      stack.erase(at + 1, stack.end());
      continue;
    }
    last_seen[size_t(v)] = f;
    stack.push_back(v);
  }
  loops.push_back(std::move(stack));
  whole = loops.size() == 1;
  std::erase_if(loops, [](const std::vector<int>& loop) { return loop.size() < 3; });
  return loops;
}

// Replaces every vertex v by target[v] (target[v] ≤ v; target[t] == t for a kept vertex), whose
// Gaussian becomes gaussians[t] where given, then drops repeated corners, degenerate faces and the
// merged-away vertices. The faces stay in their lists where no face splits into several (the lists
// then go back to arrays_of's next call, MeshArrays::~MeshArrays), and only faces with a merged
// corner are walked again. `near`: the faces (ascending) at the vertices that move or that others merge
// into, from the mesh the arrays were made of (arrays_of): the only faces the merge can change or make
// coincide, and so the only ones it reads.
MergeResult merge_into(MeshArrays in, const std::vector<int>& target,
                       const std::unordered_map<int, Gaussian>& gaussians, const std::vector<int>& near) {
  MergeResult r;
  MeshArrays& a = r.arrays;
  a = std::move(in);
  for (const auto& [v, g] : gaussians) {
    a.means[size_t(v)] = g.mean;
    a.covariances[size_t(v)] = g.covariance;
  }
  const int n_in = a.n_faces();
  // The faces with a merged corner, in order, and what each becomes.
  struct Merged {
    int face;
    bool whole;
    std::vector<std::vector<int>> loops;
  };
  std::vector<Merged> merged;
  std::vector<int> last_seen(a.means.size(), -1);
  bool splits = false;
  for (const int f : near) {
    const std::vector<int>& corners = a.faces[size_t(f)];
    if (std::all_of(corners.begin(), corners.end(), [&](int v) { return target[size_t(v)] == v; })) continue;
    Merged m{f, false, {}};
    m.loops = merged_face(corners, target, f, last_seen, m.whole);
    splits = splits || m.loops.size() > 1;
    merged.push_back(std::move(m));
  }
  // Each face in order: as it was, or what it became. In place where no face becomes several (each
  // lands at or before its own place), else into new lists.
  std::vector<int>& face_origin = a.face_origin;
  face_origin.resize(size_t(n_in), -1);  // faces past the given origins are new
  std::vector<std::vector<int>> split_faces;
  std::vector<int> split_origin;
  std::vector<std::vector<int>>& faces = splits ? split_faces : a.faces;
  std::vector<int>& put_origin = splits ? split_origin : face_origin;
  int out = 0;
  const auto put = [&](std::vector<int>&& face, int origin) {
    if (splits) {
      faces.push_back(std::move(face));
      put_origin.push_back(origin);
    } else {
      if (&face != &faces[size_t(out)]) std::swap(faces[size_t(out)], face);
      put_origin[size_t(out)] = origin;
    }
    ++out;
  };
  // The faces before the first that changed stay where they are, as they were; of the others, those
  // from `near` are listed where they land, for the check of coinciding faces below.
  size_t next_merged = 0, next_near = 0;
  std::vector<int> near_out;
  const int unchanged = splits || merged.empty() ? 0 : merged.front().face;
  out = unchanged;
  while (next_near < near.size() && near[next_near] < unchanged) near_out.push_back(near[next_near++]);
  for (int f = unchanged; f < n_in; ++f) {
    const int origin = face_origin[size_t(f)];
    const bool is_near = next_near < near.size() && near[next_near] == f;
    next_near += is_near ? 1 : 0;
    if (next_merged == merged.size() || merged[next_merged].face != f) {
      if (is_near) near_out.push_back(out);
      put(std::move(a.faces[size_t(f)]), origin);  // no corner merged: the face as it was
      continue;
    }
    Merged& m = merged[next_merged++];
    for (std::vector<int>& loop : m.loops) {
      near_out.push_back(out);
      put(std::move(loop), m.whole ? origin : -1);
    }
    r.faces_removed += m.loops.empty() ? 1 : 0;
  }
  if (splits) {
    a.faces = std::move(split_faces);
    face_origin = std::move(split_origin);
  }
  a.faces.resize(size_t(out));
  face_origin.resize(size_t(out));
  // A face that now coincides with an earlier one, corner for corner (a duplicate welded onto its
  // original), is the same face: removed. Only faces at a vertex something merged into can.
  std::vector<char> merged_into(a.means.size(), 0);
  for (size_t v = 0; v < target.size(); ++v)
    if (target[v] != int(v)) merged_into[size_t(target[v])] = 1;
  std::set<std::vector<int>> seen;
  std::vector<int> coinciding;  // ascending
  for (const int f : near_out) {
    const std::vector<int>& face = a.faces[size_t(f)];
    if (std::any_of(face.begin(), face.end(), [&](int v) { return merged_into[size_t(v)] != 0; })) {
      std::vector<int> key = face;
      std::rotate(key.begin(), std::min_element(key.begin(), key.end()), key.end());
      if (!seen.insert(std::move(key)).second) coinciding.push_back(f);
    }
  }
  if (!coinciding.empty()) {
    size_t next_face = size_t(coinciding.front()), next_coinciding = 0;
    for (size_t f = next_face; f < a.faces.size(); ++f) {
      if (next_coinciding < coinciding.size() && coinciding[next_coinciding] == int(f)) {
        ++next_coinciding;
        ++r.faces_removed;
        continue;
      }
      face_origin[next_face] = face_origin[f];
      std::swap(a.faces[next_face], a.faces[f]);
      ++next_face;
    }
    a.faces.resize(next_face);
    face_origin.resize(next_face);
  }
  r.new_index.assign(a.means.size(), -1);
  const bool origins = a.origin.size() == a.means.size();
  int next = 0;
  for (size_t v = 0; v < a.means.size(); ++v)
    if (target[v] == int(v)) {
      a.means[size_t(next)] = a.means[v];
      a.covariances[size_t(next)] = a.covariances[v];
      if (origins) a.origin[size_t(next)] = a.origin[v];
      r.new_index[v] = next++;
    }
  a.means.resize(size_t(next));
  a.covariances.resize(size_t(next));
  a.origin.resize(origins ? size_t(next) : 0);
  for (auto& face : a.faces)
    for (int& v : face) v = r.new_index[size_t(v)];
  std::vector<int> merged_index(target.size());
  for (size_t v = 0; v < merged_index.size(); ++v) merged_index[v] = r.new_index[size_t(target[v])];
  a.sharpness = renumbered(a.sharpness, merged_index, next);
  return r;
}

std::string faces_removed_text(int n) {
  if (n == 0) return "";
  return ", " + std::to_string(n) + (n == 1 ? " face" : " faces") + " removed";
}

// The faces of `mesh` (ascending) at the vertices `target` moves and at those it moves others to:
// merge_into's `near`.
std::vector<int> faces_near_merges(const CovarianceMesh& mesh, const std::vector<int>& target) {
  const MeshConnectivity& c = mesh.connectivity();
  std::vector<int> faces;
  const auto add_faces_at = [&](int v) {
    const std::span<const int> row = c.faces_of_vertex(v);
    faces.insert(faces.end(), row.begin(), row.end());
  };
  for (size_t v = 0; v < target.size(); ++v)
    if (target[v] != int(v)) add_faces_at(int(v)), add_faces_at(target[v]);
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  return faces;
}

// Union-find with the smallest index as each set's root.
int find_root(std::vector<int>& parent, int v) {
  while (parent[size_t(v)] != v) {
    parent[size_t(v)] = parent[size_t(parent[size_t(v)])];
    v = parent[size_t(v)];
  }
  return v;
}

void unite(std::vector<int>& parent, int u, int v) {
  u = find_root(parent, u);
  v = find_root(parent, v);
  if (u < v) parent[size_t(v)] = u;
  if (v < u) parent[size_t(u)] = v;
}

struct CellHash {
  size_t operator()(const std::array<int64_t, 3>& c) const {
    return size_t(uint64_t(c[0]) * 73856093u ^ uint64_t(c[1]) * 19349663u ^ uint64_t(c[2]) * 83492791u);
  }
};

}  // namespace

Modelled merge_vertices(const CovarianceMesh& mesh, const std::vector<int>& vertices, MergePoint at) {
  MeshArrays a = arrays_of(mesh);
  const std::vector<int> group = sorted_vertices(a, vertices);
  if (group.size() != vertices.size()) {
    std::vector<int> listed = vertices;
    std::sort(listed.begin(), listed.end());
    const int twice = *std::adjacent_find(listed.begin(), listed.end());
    throw Error("vertex " + std::to_string(twice) + " is listed twice");
  }
  if (group.size() < 2) throw Error("merging needs at least 2 vertices");
  const Gaussian g = at == MergePoint::center  ? group_center(a, group)
                     : at == MergePoint::first ? a.gaussian(vertices.front())
                                               : a.gaussian(vertices.back());
  std::vector<int> target(size_t(a.n_vertices()));
  std::iota(target.begin(), target.end(), 0);
  for (int v : group) target[size_t(v)] = group.front();
  MergeResult r = merge_into(std::move(a), target, {{group.front(), g}}, faces_near_merges(mesh, target));
  Modelled out = modelled(mesh, std::move(r.arrays), {r.new_index[size_t(group.front())]});
  out.summary = "merged " + std::to_string(group.size()) + " vertices into vertex " +
                std::to_string(out.selection.front()) + faces_removed_text(r.faces_removed);
  return out;
}

Modelled weld_by_distance(const CovarianceMesh& mesh, const std::vector<int>& vertices, double distance) {
  MeshArrays a = arrays_of(mesh);
  std::ostringstream d;
  d << distance;
  if (!(distance > 0) || !std::isfinite(distance))
    throw Error("the distance must be positive and finite (got " + d.str() + ")");
  std::vector<int> candidates = sorted_vertices(a, vertices);
  if (vertices.empty()) {
    candidates.resize(size_t(a.n_vertices()));
    std::iota(candidates.begin(), candidates.end(), 0);
  }
  // Cells of size `distance`: two points closer than it lie in the same or neighbouring cells.
  constexpr double kMaxCell = 1e15;  // cell coordinates stay exact integers
  std::unordered_map<std::array<int64_t, 3>, std::vector<int>, CellHash> cells;
  std::vector<std::array<int64_t, 3>> cell_of(candidates.size());
  for (size_t k = 0; k < candidates.size(); ++k) {
    const Vec3 c = a.means[size_t(candidates[k])] / distance;
    if (c.cwiseAbs().maxCoeff() > kMaxCell)
      throw Error("the distance " + d.str() + " is too small for the mesh's extent");
    cell_of[k] = {int64_t(std::floor(c[0])), int64_t(std::floor(c[1])), int64_t(std::floor(c[2]))};
    cells[cell_of[k]].push_back(candidates[k]);
  }
  std::vector<int> parent(size_t(a.n_vertices()));
  std::iota(parent.begin(), parent.end(), 0);
  const double d2 = distance * distance;
  for (size_t k = 0; k < candidates.size(); ++k) {
    const int v = candidates[k];
    for (int64_t dx = -1; dx <= 1; ++dx)
      for (int64_t dy = -1; dy <= 1; ++dy)
        for (int64_t dz = -1; dz <= 1; ++dz) {
          const auto it = cells.find({cell_of[k][0] + dx, cell_of[k][1] + dy, cell_of[k][2] + dz});
          if (it == cells.end()) continue;
          for (int w : it->second)
            if (w > v && (a.means[size_t(w)] - a.means[size_t(v)]).squaredNorm() < d2) unite(parent, v, w);
        }
  }
  std::vector<int> target(parent.size());
  std::unordered_map<int, std::vector<int>> clusters;
  for (size_t v = 0; v < parent.size(); ++v) {
    target[v] = find_root(parent, int(v));
    if (target[v] != int(v)) clusters[target[v]].push_back(int(v));
  }
  std::unordered_map<int, Gaussian> gaussians;
  int removed = 0;
  for (auto& [root, members] : clusters) {
    members.push_back(root);
    gaussians[root] = group_center(a, members);
    removed += int(members.size()) - 1;
  }
  MergeResult r = merge_into(std::move(a), target, gaussians, faces_near_merges(mesh, target));
  Modelled out = modelled(mesh, std::move(r.arrays), {});
  for (const auto& [root, members] : clusters) out.selection.push_back(r.new_index[size_t(root)]);
  std::sort(out.selection.begin(), out.selection.end());
  out.summary = "welded " + std::to_string(clusters.size()) + (clusters.size() == 1 ? " cluster" : " clusters") + ": " +
                std::to_string(removed) + (removed == 1 ? " vertex" : " vertices") + " removed" +
                faces_removed_text(r.faces_removed);
  return out;
}

Modelled merge_met_vertices(Modelled out, double distance) {
  const std::set<int> made(out.selection.begin(), out.selection.end());
  std::set<int> near;  // the new vertices and those on their faces
  for (size_t f = 0; f < out.mesh.n_faces(); ++f) {
    const std::span<const int> face = out.mesh.face(f);
    if (std::any_of(face.begin(), face.end(), [&](int v) { return made.count(v) != 0; }))
      near.insert(face.begin(), face.end());
  }
  Modelled merged = weld_by_distance(out.mesh, {near.begin(), near.end()}, distance);
  if (merged.mesh.n_vertices() == out.mesh.n_vertices()) return out;
  // Each vertex of the merged mesh: a new one if it was one or is a merged group.
  std::vector<int> selection, origin(merged.mesh.n_vertices(), -1);
  const std::set<int> joined(merged.selection.begin(), merged.selection.end());
  const bool known = merged.vertex_origin.size() == merged.mesh.n_vertices();
  for (size_t w = 0; w < merged.mesh.n_vertices(); ++w) {
    const int before = known ? merged.vertex_origin[w] : -1;
    if (made.count(before) != 0 || joined.count(int(w)) != 0) selection.push_back(int(w));
    if (before >= 0 && size_t(before) < out.vertex_origin.size()) origin[w] = out.vertex_origin[size_t(before)];
  }
  out.summary += "; " + std::to_string(out.mesh.n_vertices() - merged.mesh.n_vertices()) +
                 (out.mesh.n_vertices() - merged.mesh.n_vertices() == 1 ? " vertex" : " vertices") +
                 " that met merged, leaving " + std::to_string(merged.mesh.n_vertices()) + " vertices and " +
                 std::to_string(merged.mesh.n_faces()) + " faces";
  merged.selection = std::move(selection);
  merged.summary = std::move(out.summary);
  merged.vertex_origin = known && !out.vertex_origin.empty() ? std::move(origin) : std::vector<int>{};
  return merged;
}

}  // namespace gps
