#include "core/patch_readers.h"

#include <algorithm>

#include "core/error.h"

namespace gps {

namespace {

// The points a patch's plan nodes read (core/plan_table.h): a walk from its root.
void collect_node_points(const PlanTable& plans, int node, std::vector<int>& out) {
  const int32_t* n = plans.nodes.data() + node;
  const auto kind = NodeKind(n[0]);
  if (kind == NodeKind::internal) {
    for (int c = 1; c <= 4; ++c) collect_node_points(plans, n[c], out);
  } else if (kind == NodeKind::extraordinary) {  // corner, table, K, then K points
    out.insert(out.end(), n + 4, n + 4 + n[3]);
  } else {
    const int net = plans.shape == PatchShape::triangle ? 12 : 16;
    out.insert(out.end(), n + 1, n + 1 + net);
  }
}

// The transpose of rows `offsets`/`values` (row r holds values[offsets[r] .. offsets[r+1])) over
// `n_columns` columns: per column the rows holding it, in increasing order (a counting sort).
void transpose(const std::vector<int>& offsets, const std::vector<int>& values, int n_columns, std::vector<int>& out_offsets,
               std::vector<int>& out_values) {
  out_offsets.assign(size_t(n_columns) + 1, 0);
  for (const int c : values) ++out_offsets[size_t(c) + 1];
  for (size_t c = 0; c < size_t(n_columns); ++c) out_offsets[c + 1] += out_offsets[c];
  out_values.resize(values.size());
  std::vector<int> next(out_offsets.begin(), out_offsets.end() - 1);
  for (size_t r = 0; r + 1 < offsets.size(); ++r)
    for (int i = offsets[r]; i < offsets[r + 1]; ++i) out_values[size_t(next[size_t(values[size_t(i)])]++)] = int(r);
}

}  // namespace

PatchReaders::PatchReaders(const PlanTable& plans, int n_points) : n_patches_(plans.n_patches()) {
  const int corners = plans.corners();
  // Per patch: the points it reads, and the patches it evaluates boundary points from.
  std::vector<int> read_offsets{0}, reads, source_offsets{0}, sources, points;
  for (int p = 0; p < n_patches_; ++p) {
    points.clear();
    collect_node_points(plans, plans.patch_roots[size_t(p)], points);
    const auto corner = plans.patch_corner_points.begin() + ptrdiff_t(corners) * p;
    points.insert(points.end(), corner, corner + corners);
    if (!plans.patch_edges.empty())
      for (int k = 0; k < corners; ++k) {
        const PatchEdge e = patch_edge(plans, p, k);
        points.insert(points.end(), {e.from, e.to});
      }
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
  transpose(read_offsets, reads, n_points, point_offsets_, point_patches_);
  transpose(source_offsets, sources, n_patches_, canonical_offsets_, canonical_users_);
}

std::vector<int> PatchReaders::patches_changed_by(const std::vector<int>& points) const {
  std::vector<int> read;
  for (const int point : points)
    read.insert(read.end(), point_patches_.begin() + point_offsets_[size_t(point)],
                point_patches_.begin() + point_offsets_[size_t(point) + 1]);
  std::sort(read.begin(), read.end());
  read.erase(std::unique(read.begin(), read.end()), read.end());
  std::vector<int> out = read;
  for (const int p : read)
    out.insert(out.end(), canonical_users_.begin() + canonical_offsets_[size_t(p)],
               canonical_users_.begin() + canonical_offsets_[size_t(p) + 1]);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace gps
