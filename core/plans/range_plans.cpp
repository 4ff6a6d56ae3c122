#include "core/plans/range_plans.h"

#include <algorithm>
#include <bit>
#include <exception>
#include <map>
#include <utility>

#include "core/plans/stencil_table.h"
#include "core/support/hash_mix.h"

namespace gps {

namespace {

// A range's row keys, hashed where the range has none (StencilTableBuilder::row_key).
void hash_rows(RangePlans& range) {
  const StencilTable& s = range.tables.stencils;
  if (range.row_keys.size() == size_t(s.n_rows())) return;
  range.row_keys.resize(size_t(s.n_rows()));
  for (int row = 0; row < s.n_rows(); ++row) range.row_keys[size_t(row)] = StencilTableBuilder::row_key(s, row);
}

}  // namespace

SurfaceTables merge_ranges(std::vector<RangePlans>& ranges, int n_base, bool release, const SurfaceTables* previous,
                           size_t same_leading, SurfaceTables* storage, std::vector<KeptStencilRows>* kept_rows,
                           size_t storage_leading, LeadingRecords* same) {
  PatchPlans plans;
  struct {
    size_t nodes = 0, patches = 0;
  } held;         // the records the storage holds
  if (storage) {  // every element past the storage's leading part is written
    held = {storage->plans.nodes.size(), storage->plans.patch_roots.size()};
    plans.nodes = std::move(storage->plans.nodes);
    plans.patch_roots = std::move(storage->plans.patch_roots);
    plans.patch_corner_points = std::move(storage->plans.patch_corner_points);
    plans.patch_edges = std::move(storage->plans.patch_edges);
  }
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
    // The rows' keys on all cores (kept: a range merged again is not hashed again), then the rows merged.
#pragma omp parallel for schedule(dynamic)
  for (size_t r = 0; r < ranges.size(); ++r) hash_rows(ranges[r]);
  // Where each range's records start in the whole table.
  std::vector<size_t> node_base(ranges.size() + 1, 0), patch_base(ranges.size() + 1, 0);
  for (size_t r = 0; r < ranges.size(); ++r) {
    const PatchPlans& p = ranges[r].tables.plans;
    plans.max_depth = std::max(plans.max_depth, p.max_depth);
    node_base[r + 1] = node_base[r] + p.nodes.size();
    patch_base[r + 1] = patch_base[r] + p.patch_roots.size();
  }
  same_leading = std::min(same_leading, ranges.size());
  if (!previous || previous->stencils.first_row() != row_start_for(n_base) || previous->plans.shape != plans.shape ||
      previous->plans.nodes.size() < node_base[same_leading] ||
      previous->plans.patch_roots.size() < patch_base[same_leading])
    same_leading = 0;
  if (same) *same = {patch_base[same_leading], node_base[same_leading]};
  // What the storage holds of the first ranges is read only where it was merged as this merge merges.
  storage_leading = std::min(storage_leading, same_leading);
  if (!storage || storage->stencils.first_row() != row_start_for(n_base) || storage->plans.shape != plans.shape ||
      held.nodes < node_base[storage_leading] || held.patches < patch_base[storage_leading])
    storage_leading = 0;
  std::vector<const StencilTable*> range_stencils(ranges.size());
  std::vector<const std::vector<size_t>*> range_keys(ranges.size());
  std::vector<StencilRowFirsts*> range_firsts(release ? 0 : ranges.size());  // kept ranges: kept for the next merge
  for (size_t r = 0; r < ranges.size(); ++r) {
    range_stencils[r] = &ranges[r].tables.stencils;
    range_keys[r] = &ranges[r].row_keys;
    if (!release) range_firsts[r] = &ranges[r].row_firsts;
  }
  MergedStencilRows stencils =
      merge_stencil_rows(range_stencils, range_keys, n_base, row_start_for(n_base), range_firsts,
                         storage ? &storage->stencils : nullptr, storage_leading);
  if (kept_rows) *kept_rows = std::move(stencils.kept);
  const std::vector<std::vector<int>>& rows = stencils.points;  // per range: local row -> point in the whole table
  plans.nodes.resize(node_base.back());
  plans.patch_roots.resize(patch_base.back());
  plans.patch_corner_points.resize(corners * patch_base.back());
  if (plans.shape == PatchShape::quad)
    plans.patch_edges.resize(kPatchEdgeStride * patch_base.back());
  else
    plans.patch_edges.clear();  // triangles have none
  // The leading ranges merged before: their records are where they were, with the same rows and tables.
  const size_t edge_stride = plans.shape == PatchShape::quad ? kPatchEdgeStride : 0;
  if (same_leading > storage_leading) {  // copied from `previous` past what the storage holds
    const PatchPlans& q = previous->plans;
    const auto copy_part = [](const std::vector<int32_t>& from, std::vector<int32_t>& to, size_t begin, size_t end) {
      std::copy(from.begin() + long(begin), from.begin() + long(end), to.begin() + long(begin));
    };
    const size_t a = storage_leading, b = same_leading;
    copy_part(q.nodes, plans.nodes, node_base[a], node_base[b]);
    copy_part(q.patch_roots, plans.patch_roots, patch_base[a], patch_base[b]);
    copy_part(q.patch_corner_points, plans.patch_corner_points, corners * patch_base[a], corners * patch_base[b]);
    copy_part(q.patch_edges, plans.patch_edges, edge_stride * patch_base[a], edge_stride * patch_base[b]);
  }
#pragma omp parallel for schedule(dynamic)
  for (size_t r = same_leading; r < ranges.size(); ++r) {
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
  if (release)
    for (size_t r = 0; r < same_leading; ++r) ranges[r] = {};
  return {std::move(plans), std::move(stencils.table)};
}

SurfaceTables build_in_ranges(int n_faces, int n_base, const std::function<RangePlans(int, int)>& build_range) {
  const int n_ranges = std::max(1, (n_faces + kFacesPerRange - 1) / kFacesPerRange);
  std::vector<RangePlans> parts(static_cast<size_t>(n_ranges));
  std::vector<std::exception_ptr> failures(parts.size());
#pragma omp parallel for schedule(dynamic)
  for (int r = 0; r < n_ranges; ++r) {
    try {
      parts[size_t(r)] = build_range(r * kFacesPerRange, std::min(n_faces, (r + 1) * kFacesPerRange));
    } catch (...) {
      failures[size_t(r)] = std::current_exception();
    }
  }
  for (const auto& failure : failures)
    if (failure) std::rethrow_exception(failure);
  return merge_ranges(parts, n_base, true);
}

bool cut_range(const RangePlans& range, int first, int last, RangePlans& piece) {
  const PatchPlans& p = range.tables.plans;
  const StencilTable& s = range.tables.stencils;
  const int n_own = s.n_base, n_patches = p.n_patches();
  const size_t corners = size_t(p.corners()), leaf_points = p.shape == PatchShape::quad ? 16 : 12;
  const auto patch_end = [&](int patch) {
    return size_t(patch + 1 < n_patches ? p.patch_roots[size_t(patch) + 1] : int(p.nodes.size()));
  };
  if (first < 0 || first >= last || last > n_patches) return false;
  const size_t begin = size_t(p.patch_roots[size_t(first)]), end = patch_end(last - 1);
  if (end <= begin || end > p.nodes.size()) return false;
  PatchPlans& q = piece.tables.plans;
  q = {};
  q.shape = p.shape;
  q.nodes.assign(p.nodes.begin() + long(begin), p.nodes.begin() + long(end));
  piece.extraordinary_tables.clear();
  std::vector<int> new_row(size_t(s.n_rows()), -1), old_row;  // old row → its number here, and back
  std::vector<int> new_table(range.extraordinary_tables.size(), -1);
  const auto point = [&](int32_t& x) {
    if (x < n_own) return;
    int& row = new_row[size_t(x - n_own)];
    if (row < 0) row = int(old_row.size()), old_row.push_back(x - n_own);
    x = n_own + row;
  };
  // Each record's depth, set by its parent (a patch's root: 0, or 1 for a split face's half-size patch,
  // as the builders count), read when the record is reached: a record not reached breaks the run.
  std::vector<int8_t> depth(q.nodes.size(), -1);
  for (int patch = first; patch < last; ++patch) {
    const size_t root = size_t(p.patch_roots[size_t(patch)]), stop = patch_end(patch);
    if (root < begin || stop <= root || stop > end) return false;
    depth[root - begin] = half_size_patch(p, patch) ? 1 : 0;
    for (size_t o = root - begin; o < stop - begin;) {
      if (depth[o] < 0) return false;
      q.max_depth = std::max(q.max_depth, int32_t(depth[o]));
      const auto kind = NodeKind(node_kind(q.nodes[o]));
      if (kind == NodeKind::extraordinary) {  // corner, table, K, K points
        if (o + 4 > stop - begin) return false;
        int& table = new_table[size_t(q.nodes[o + 2])];
        if (table < 0) {
          table = int(piece.extraordinary_tables.size());
          piece.extraordinary_tables.push_back(range.extraordinary_tables[size_t(q.nodes[o + 2])]);
        }
        q.nodes[o + 2] = table;
        const size_t k = size_t(q.nodes[o + 3]);
        if (o + 4 + k > stop - begin) return false;
        for (size_t i = o + 4; i < o + 4 + k; ++i) point(q.nodes[i]);
        o += 4 + k;
        continue;
      }
      const size_t n = kind == NodeKind::internal ? 4 : leaf_points;
      if (o + n + 1 > stop - begin) return false;
      for (size_t i = o + 1; i <= o + n; ++i) {
        if (kind != NodeKind::internal) {
          point(q.nodes[i]);
          continue;
        }
        const size_t child = size_t(q.nodes[i]);
        if (child <= o + begin || child >= stop) return false;
        depth[child - begin] = int8_t(depth[o] + 1);
        q.nodes[i] = int32_t(child - begin);
      }
      o += n + 1;
    }
    q.patch_roots.push_back(int32_t(root - begin));
    for (size_t i = corners * size_t(patch); i < corners * size_t(patch + 1); ++i) {
      q.patch_corner_points.push_back(p.patch_corner_points[i]);
      point(q.patch_corner_points.back());
    }
    if (p.shape != PatchShape::quad) continue;
    for (size_t i = kPatchEdgeStride * size_t(patch); i < kPatchEdgeStride * size_t(patch + 1); i += kPatchEdgeInts) {
      q.patch_edges.insert(q.patch_edges.end(), {p.patch_edges[i], p.patch_edges[i + 1], p.patch_edges[i + 2]});
      point(q.patch_edges[q.patch_edges.size() - 3]);
      point(q.patch_edges[q.patch_edges.size() - 2]);
    }
  }
  StencilTable& t = piece.tables.stencils;
  t = {};
  t.n_base = n_own;
  t.offsets.reserve(old_row.size() + 1);
  t.offsets.push_back(0);
  for (const int row : old_row) {
    const auto from = s.offsets[size_t(row)], to = s.offsets[size_t(row) + 1];
    t.indices.insert(t.indices.end(), s.indices.begin() + from, s.indices.begin() + to);
    t.weights.insert(t.weights.end(), s.weights.begin() + from, s.weights.begin() + to);
    t.offsets.push_back(int32_t(t.indices.size()));
  }
  piece.row_keys.clear();
  piece.row_firsts = {};
  if (range.row_keys.size() == size_t(s.n_rows()))
    for (const int row : old_row) piece.row_keys.push_back(range.row_keys[size_t(row)]);
  return true;
}

namespace {

// Whether what a merge found of a table's `n_rows` rows is whole: the table was merged, and each row has
// its record.
bool followed_firsts(const StencilRowFirsts& f, int n_rows) {
  const size_t n = size_t(n_rows);
  return f.table != 0 && f.of_table.size() == n && f.of_row.size() == n && f.merged_row.size() == n;
}

// Per row of table b, the row of table a with the same terms (−1: none), found by the rows' keys: the
// table with fewer rows is laid out in a flat hash table, the other's rows looked up in it.
std::vector<int> rows_alike(const StencilTable& a, const std::vector<size_t>& a_keys, const StencilTable& b,
                            const std::vector<size_t>& b_keys) {
  std::vector<int> alike(size_t(b.n_rows()), -1);
  const bool laid_out_a = a.n_rows() <= b.n_rows();
  const std::vector<size_t>& laid_keys = laid_out_a ? a_keys : b_keys;
  const std::vector<size_t>& looked_keys = laid_out_a ? b_keys : a_keys;
  const size_t mask = std::bit_ceil(2 * laid_keys.size() + 1) - 1;
  std::vector<int> slot_row(mask + 1, -1);
  for (size_t row = 0; row < laid_keys.size(); ++row) {
    size_t at = size_t(mixed_hash(laid_keys[row])) & mask;
    while (slot_row[at] >= 0) at = (at + 1) & mask;
    slot_row[at] = int(row);
  }
  for (size_t row = 0; row < looked_keys.size(); ++row)
    for (size_t at = size_t(mixed_hash(looked_keys[row])) & mask; slot_row[at] >= 0; at = (at + 1) & mask) {
      const int laid = slot_row[at];
      if (laid_keys[size_t(laid)] != looked_keys[row]) continue;
      const int row_a = laid_out_a ? laid : int(row), row_b = laid_out_a ? int(row) : laid;
      if (!same_row_terms(a, row_a, b, row_b)) continue;
      alike[size_t(row_b)] = row_a;
      break;
    }
  return alike;
}

}  // namespace

AppendedRows append_range(RangePlans& range, const RangePlans& next) {
  PatchPlans& p = range.tables.plans;
  StencilTable& s = range.tables.stencils;
  const PatchPlans& q = next.tables.plans;
  const StencilTable& t = next.tables.stencils;
  if (p.patch_roots.empty() && s.n_rows() == 0) {  // next as it is, under its own id
    range = next;
    return {};
  }
  hash_rows(range);
  // The range's own rows follow the larger base.
  const int n_base = std::max(s.n_base, t.n_base);
  if (const int own = s.n_base; own != n_base)
    for_each_point(p, [own, n_base](int32_t& x) { x = x < own ? x : x - own + n_base; });
  s.n_base = n_base;
  // What the last merge found of both ranges' rows is kept where both have it (followed_firsts).
  StencilRowFirsts& firsts = range.row_firsts;
  const StencilRowFirsts& next_firsts = next.row_firsts;
  const bool followed = followed_firsts(firsts, s.n_rows()) && followed_firsts(next_firsts, t.n_rows());
  if (!followed) firsts = {};
  // next's rows: those whose terms the range holds are that row, the others are appended.
  std::vector<size_t> next_keys;
  if (next.row_keys.size() != size_t(t.n_rows()))
    for (int row = 0; row < t.n_rows(); ++row) next_keys.push_back(StencilTableBuilder::row_key(t, row));
  const std::vector<size_t>& keys = next_keys.empty() ? next.row_keys : next_keys;
  std::vector<int> row_of = rows_alike(s, range.row_keys, t, keys);  // next's row → the range's
  for (int row = 0; row < t.n_rows(); ++row) {
    if (row_of[size_t(row)] >= 0) continue;
    row_of[size_t(row)] = s.n_rows();
    const auto from = t.offsets[size_t(row)], to = t.offsets[size_t(row) + 1];
    s.indices.insert(s.indices.end(), t.indices.begin() + from, t.indices.begin() + to);
    s.weights.insert(s.weights.end(), t.weights.begin() + from, t.weights.begin() + to);
    s.offsets.push_back(int32_t(s.indices.size()));
    range.row_keys.push_back(keys[size_t(row)]);
    if (!followed) continue;
    // An appended row's terms came first where they did, or, where that was in `next`, in its row here.
    const long long of_table = next_firsts.of_table[size_t(row)];
    firsts.of_table.push_back(of_table == next_firsts.table ? firsts.table : of_table);
    firsts.of_row.push_back(of_table == next_firsts.table ? -1 - next_firsts.of_row[size_t(row)]
                                                          : next_firsts.of_row[size_t(row)]);
    firsts.merged_row.push_back(next_firsts.merged_row[size_t(row)]);
  }
  if (followed)
    for (int& of_row : firsts.of_row)
      if (of_row < 0) of_row = row_of[size_t(-1 - of_row)];
  // next's extraordinary tables: those the range holds are not repeated.
  std::vector<int> table_of(next.extraordinary_tables.size());
  for (size_t i = 0; i < table_of.size(); ++i) {
    const auto at =
        std::find(range.extraordinary_tables.begin(), range.extraordinary_tables.end(), next.extraordinary_tables[i]);
    table_of[i] = int(at - range.extraordinary_tables.begin());
    if (at == range.extraordinary_tables.end()) range.extraordinary_tables.push_back(next.extraordinary_tables[i]);
  }
  // next's records after the range's: children and roots past its nodes, points and tables renumbered.
  PatchPlans added = q;
  const int32_t node_base = int32_t(p.nodes.size()), own = t.n_base;
  for_each_point(added, [&](int32_t& x) { x = x < own ? x : n_base + row_of[size_t(x - own)]; });
  const size_t leaf_points = q.shape == PatchShape::quad ? 16 : 12;
  for (size_t o = 0; o < added.nodes.size();) {
    const auto kind = NodeKind(node_kind(added.nodes[o]));
    if (kind == NodeKind::extraordinary) {  // corner, table, K, K points
      added.nodes[o + 2] = table_of[size_t(added.nodes[o + 2])];
      o += 4 + size_t(added.nodes[o + 3]);
      continue;
    }
    const size_t n = kind == NodeKind::internal ? 4 : leaf_points;
    if (kind == NodeKind::internal)
      for (size_t i = o + 1; i <= o + n; ++i) added.nodes[i] += node_base;
    o += n + 1;
  }
  for (int32_t& root : added.patch_roots) root += node_base;
  p.max_depth = std::max(p.max_depth, q.max_depth);
  p.nodes.insert(p.nodes.end(), added.nodes.begin(), added.nodes.end());
  p.patch_roots.insert(p.patch_roots.end(), added.patch_roots.begin(), added.patch_roots.end());
  p.patch_corner_points.insert(p.patch_corner_points.end(), added.patch_corner_points.begin(),
                               added.patch_corner_points.end());
  p.patch_edges.insert(p.patch_edges.end(), added.patch_edges.begin(), added.patch_edges.end());
  if (!followed) return {};
  return {next_firsts.table, firsts.table, std::move(row_of)};
}

}  // namespace gps
