#pragma once
// The rows of several stencil tables over the same base vertices merged into one table, each distinct
// row once, where it first comes (docs/design.md §2 step 3): what adding every row of every table in
// turn to one StencilTableBuilder gives, bit for bit. Found on all cores, or, where the tables were
// merged before and most are kept, from where each row first came then.
#include <cstddef>
#include <vector>

#include "core/plans/patch_plans.h"

namespace gps {

/// What a merge found of one table's rows, kept with the table for the next merge: the rows that come
/// first in a merge are those that came first in the one before but where a table merged then is gone,
/// or a new one holds the same terms. Cleared (reset to {}) wherever the table's rows change, but for a
/// renumbering of the base vertices that is one to one and the same for every table kept, and for the
/// rows of the next table of the same merge appended (append_range, core/plans/range_plans.h).
struct StencilRowFirsts {
  long long table = 0;              // the table's id in the merges (0: not merged yet)
  int position = -1;                // its place among the tables of its last merge
  std::vector<long long> of_table;  // per row: the table (id) and its row where the row's terms first came
  std::vector<int> of_row;
  std::vector<int> merged_row;  // per row: the merged table's row that holds its terms
};

/// The rows of a merged table (id `from`) appended to another of the same merge (id `to`, append_range in
/// core/plans/range_plans.h): per row of `from`, the row of `to` that holds its terms.
struct AppendedRows {
  long long from = 0, to = 0;
  std::vector<int> rows;
};

/// Names, in what a merge found of a table, the row each appended row became wherever it named the
/// appended one as where its terms first came: the next merge follows it there.
void rename_appended_rows(StencilRowFirsts& firsts, const std::vector<AppendedRows>& appended);

/// Rows [first, first + count) of a merged table have the terms of rows [old_first, old_first + count)
/// of the table the merge before made.
struct KeptStencilRows {
  int first = 0, old_first = 0, count = 0;
  bool operator==(const KeptStencilRows&) const = default;
};

struct MergedStencilRows {
  StencilTable table;
  std::vector<std::vector<int>> points;  // per table, per row: its point index in `table`
  std::vector<KeptStencilRows> kept;     // where the last merge's firsts were followed: the rows of kept tables
};

/// Merges the rows of `tables` (no zero weight, as StencilTableBuilder makes them) in order (table 0's
/// rows first), rows with the same terms shared. `keys[t][r]`: StencilTableBuilder::row_key of row r of
/// table t. The merged rows are numbered from point `first_row` on, past `n_base` base vertices.
/// `firsts`: none, or per table what the last merge found of it, read and updated. `storage`: a table
/// no longer used, whose arrays the merged table is written into; `storage_leading`: the first tables
/// whose rows it holds already as they are merged here (merged from these tables too), not written again.
MergedStencilRows merge_stencil_rows(const std::vector<const StencilTable*>& tables,
                                     const std::vector<const std::vector<size_t>*>& keys, int n_base, int first_row,
                                     const std::vector<StencilRowFirsts*>& firsts = {}, StencilTable* storage = nullptr,
                                     size_t storage_leading = 0);

}  // namespace gps
