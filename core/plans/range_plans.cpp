#include "core/plans/range_plans.h"

#include <algorithm>
#include <map>

#include "core/plans/stencil_table.h"

namespace gps {

SurfaceTables merge_ranges(std::vector<RangePlans>& ranges, int n_base, bool release) {
  StencilTableBuilder stencils(n_base);
  PatchPlans plans;
  if (!ranges.empty()) plans.shape = ranges.front().tables.plans.shape;
  const size_t corners = size_t(plans.corners()), leaf_points = plans.shape == PatchShape::quad ? 16 : 12;
  std::vector<std::vector<int>> extraordinary_offset(ranges.size());  // per range: table index -> offset in the whole
  std::map<const std::vector<double>*, int> laid_out;
  for (size_t r = 0; r < ranges.size(); ++r)
    for (const auto& table : ranges[r].extraordinary_tables) {
      const auto [at, added] = laid_out.try_emplace(table.get(), int(plans.extraordinary_tables.size()));
      if (added) plans.extraordinary_tables.insert(plans.extraordinary_tables.end(), table->begin(), table->end());
      extraordinary_offset[r].push_back(at->second);
    }
  // The rows' keys on all cores (kept: a range merged again is not hashed again), then the rows in order.
  size_t n_rows = 0;
#pragma omp parallel for schedule(dynamic) reduction(+ : n_rows)
  for (size_t r = 0; r < ranges.size(); ++r) {
    const StencilTable& s = ranges[r].tables.stencils;
    std::vector<size_t>& keys = ranges[r].row_keys;
    if (keys.size() != size_t(s.n_rows())) {
      keys.resize(size_t(s.n_rows()));
      for (int row = 0; row < s.n_rows(); ++row) keys[size_t(row)] = StencilTableBuilder::row_key(s, row);
    }
    n_rows += size_t(s.n_rows());
  }
  stencils.reserve_lookup(n_rows);
  std::vector<std::vector<int>> rows(ranges.size());  // per range: local row -> point in the whole table
  for (size_t r = 0; r < ranges.size(); ++r) {
    const StencilTable& s = ranges[r].tables.stencils;
    rows[r].resize(size_t(s.n_rows()));
    for (int row = 0; row < s.n_rows(); ++row)
      rows[r][size_t(row)] = stencils.add_row(s, row, ranges[r].row_keys[size_t(row)]);
  }
  // Where each range's records start in the whole table.
  std::vector<size_t> node_base(ranges.size() + 1, 0), patch_base(ranges.size() + 1, 0);
  for (size_t r = 0; r < ranges.size(); ++r) {
    const PatchPlans& p = ranges[r].tables.plans;
    plans.max_depth = std::max(plans.max_depth, p.max_depth);
    node_base[r + 1] = node_base[r] + p.nodes.size();
    patch_base[r + 1] = patch_base[r] + p.patch_roots.size();
  }
  plans.nodes.resize(node_base.back());
  plans.patch_roots.resize(patch_base.back());
  plans.patch_corner_points.resize(corners * patch_base.back());
  if (plans.shape == PatchShape::quad) plans.patch_edges.resize(kPatchEdgeStride * patch_base.back());
#pragma omp parallel for schedule(dynamic)
  for (size_t r = 0; r < ranges.size(); ++r) {
    const PatchPlans& p = ranges[r].tables.plans;
    // A range's own points follow its own base (a kept range's may be older than the mesh's: its base
    // vertices kept their indices, core/plans/surface_replanner.cpp).
    const int own = ranges[r].tables.stencils.n_base;
    const auto point = [&row = rows[r], own](int p) { return p < own ? p : row[size_t(p - own)]; };
    const int base = int(node_base[r]);
    int32_t* nodes = plans.nodes.data() + node_base[r];
    for (size_t o = 0; o < p.nodes.size();) {  // node records: kind, then children, points or a table
      const auto kind = NodeKind(node_kind(p.nodes[o]));
      nodes[o] = p.nodes[o];
      if (kind == NodeKind::extraordinary) {  // corner, table, K, K points
        const size_t k = size_t(p.nodes[o + 3]);
        nodes[o + 1] = p.nodes[o + 1];
        nodes[o + 2] = extraordinary_offset[r][size_t(p.nodes[o + 2])];
        nodes[o + 3] = p.nodes[o + 3];
        for (size_t i = o + 4; i < o + 4 + k; ++i) nodes[i] = point(p.nodes[i]);
        o += 4 + k;
        continue;
      }
      const size_t n = kind == NodeKind::internal ? 4 : leaf_points;
      for (size_t i = o + 1; i <= o + n; ++i)
        nodes[i] = kind == NodeKind::internal ? base + p.nodes[i] : point(p.nodes[i]);
      o += n + 1;
    }
    const size_t first = patch_base[r];
    for (size_t i = 0; i < p.patch_roots.size(); ++i) plans.patch_roots[first + i] = base + p.patch_roots[i];
    for (size_t i = 0; i < p.patch_corner_points.size(); ++i)
      plans.patch_corner_points[corners * first + i] = point(p.patch_corner_points[i]);
    const size_t edges = kPatchEdgeStride * first;  // none for triangles
    for (size_t i = 0; i < p.patch_edges.size(); i += kPatchEdgeInts) {  // from, to, part
      plans.patch_edges[edges + i] = point(p.patch_edges[i]);
      plans.patch_edges[edges + i + 1] = point(p.patch_edges[i + 1]);
      plans.patch_edges[edges + i + 2] = p.patch_edges[i + 2];
    }
    if (release) ranges[r] = {};
  }
  return {std::move(plans), stencils.finish()};
}

}  // namespace gps
