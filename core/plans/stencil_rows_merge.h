#pragma once
// The rows of several stencil tables over the same base vertices merged into one table, each distinct
// row once, where it first comes (docs/design.md §2 step 3): what adding every row of every table in
// turn to one StencilTableBuilder gives, bit for bit, found on all cores.
#include <cstddef>
#include <vector>

#include "core/plans/patch_plans.h"

namespace gps {

struct MergedStencilRows {
  StencilTable table;
  std::vector<std::vector<int>> points;  // per table, per row: its point index in `table`
};

/// Merges the rows of `tables` in order (table 0's rows first), rows with the same terms shared.
/// `keys[t][r]`: StencilTableBuilder::row_key of row r of table t. The merged rows are numbered from
/// point `first_row` on, past `n_base` base vertices.
MergedStencilRows merge_stencil_rows(const std::vector<const StencilTable*>& tables,
                                     const std::vector<const std::vector<size_t>*>& keys, int n_base, int first_row);

}  // namespace gps
