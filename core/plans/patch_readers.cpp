#include "core/plans/patch_readers.h"

#include <algorithm>

#include "core/support/error.h"
#include "core/mesh/sparse_lists.h"
#include "core/plans/surface_replanner.h"

namespace gps {

namespace {

// The points a patch's plan nodes read (core/plans/patch_plans.h): a walk from its root.
void collect_node_points(const PatchPlans& plans, int node, std::vector<int>& out) {
  const int32_t* n = plans.nodes.data() + node;
  const auto kind = NodeKind(node_kind(n[0]));
  if (kind == NodeKind::internal) {
    for (int c = 1; c <= 4; ++c) collect_node_points(plans, n[c], out);
  } else if (kind == NodeKind::extraordinary) {  // corner, table, K, then K points
    out.insert(out.end(), n + 4, n + 4 + n[3]);
  } else {
    const int net = plans.shape == PatchShape::triangle ? 12 : 16;
    out.insert(out.end(), n + 1, n + 1 + net);
  }
}

}  // namespace

void append_patch_points(const PatchPlans& plans, int p, std::vector<int>& out) {
  const int corners = plans.corners();
  collect_node_points(plans, plans.patch_roots[size_t(p)], out);
  const auto corner = plans.patch_corner_points.begin() + ptrdiff_t(corners) * p;
  out.insert(out.end(), corner, corner + corners);
  if (!plans.patch_edges.empty())
    for (int k = 0; k < corners; ++k) {
      const PatchEdge e = patch_edge(plans, p, k);
      out.insert(out.end(), {e.from, e.to});
    }
}

PatchReaders::PatchReaders(const PatchPlans& plans, int n_points) : n_patches_(plans.n_patches()) {
  const int corners = plans.corners();
  // Per patch: the points it reads, and the patches it evaluates boundary points from.
  std::vector<int> read_offsets{0}, reads, source_offsets{0}, sources, points;
  for (int p = 0; p < n_patches_; ++p) {
    points.clear();
    append_patch_points(plans, p, points);
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (!points.empty() && (points.front() < 0 || points.back() >= n_points)) throw Error("plan point out of range");
    reads.insert(reads.end(), points.begin(), points.end());
    read_offsets.push_back(int(reads.size()));
    // The patches across the edges (both halves of a whole edge beside halves) and the corners' owners.
    for (int k = 0; k < corners; ++k) {
      const int32_t* r = &plans.patch_neighbours[size_t(4 * (corners * p + k))];
      for (const int q : {r[0], r[2], plans.corner_owners[size_t(2 * (corners * p + k))]})
        if (q >= 0 && q != p) sources.push_back(q);
    }
    std::sort(sources.begin() + source_offsets.back(), sources.end());
    sources.erase(std::unique(sources.begin() + source_offsets.back(), sources.end()), sources.end());
    source_offsets.push_back(int(sources.size()));
  }
  transpose_lists(read_offsets, reads, n_points, point_offsets_, point_patches_);
  transpose_lists(source_offsets, sources, n_patches_, canonical_offsets_, canonical_users_);
}

std::vector<int> PatchReaders::patches_changed_by(const std::vector<int>& points) const {
  const std::vector<int> read = union_of_lists(point_offsets_, point_patches_, points);
  std::vector<int> out = union_of_lists(canonical_offsets_, canonical_users_, read);
  out.insert(out.end(), read.begin(), read.end());  // the readers themselves, then merged in order
  std::inplace_merge(out.begin(), out.end() - ptrdiff_t(read.size()), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<int> patches_changed_near(const PolygonTopology& t, const MeshConnectivity& c, const PatchPlans& plans,
                                      const std::vector<int>& first, int first_row, const std::vector<int>& vertices,
                                      const std::vector<int>& rows) {
  std::vector<int> points = vertices;
  for (const int r : rows) points.push_back(first_row + r);
  std::sort(points.begin(), points.end());
  const auto is_point = [&](int q) { return std::binary_search(points.begin(), points.end(), q); };
  const auto face_of = [&](int p) { return int(std::upper_bound(first.begin(), first.end(), p) - first.begin()) - 1; };
  // The readers, among the patches of the faces whose plans read the vertices.
  std::vector<int> read, read_faces, own;
  for (const int f : faces_reading(t, c, {}, vertices))
    for (int p = first[size_t(f)]; p < first[size_t(f) + 1]; ++p) {
      own.clear();
      append_patch_points(plans, p, own);
      if (std::any_of(own.begin(), own.end(), is_point)) read.push_back(p), read_faces.push_back(face_of(p));
    }
  std::sort(read.begin(), read.end());
  std::sort(read_faces.begin(), read_faces.end());
  read_faces.erase(std::unique(read_faces.begin(), read_faces.end()), read_faces.end());
  // Their canonical users: the patches around whose edge records or corner owners name one of them (a
  // patch across an edge or with a corner point in common lies on a face sharing a vertex with its face).
  const auto is_read = [&](int q) { return std::binary_search(read.begin(), read.end(), q); };
  const int n = plans.corners();
  std::vector<int> out = read;
  for (const int f : faces_around(t, c, read_faces))
    for (int q = first[size_t(f)]; q < first[size_t(f) + 1]; ++q)
      for (int k = 0; k < n; ++k) {
        const int32_t* r = &plans.patch_neighbours[size_t(4 * (n * q + k))];
        const int owner = plans.corner_owners[size_t(2 * (n * q + k))];
        if ((r[0] != q && is_read(r[0])) || (r[2] != q && is_read(r[2])) || (owner != q && is_read(owner))) {
          out.push_back(q);
          break;
        }
      }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace gps
