#include "core/plans/stencil_rows_merge.h"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <utility>
#include <vector>

#include "core/plans/stencil_table.h"

namespace gps {
namespace {

using Terms = std::vector<std::pair<int, double>>;

// Tables whose rows are drawn from a pool, so that rows repeat within a table and across tables;
// some rows carry zero weights, which a merge skips.
std::vector<StencilTable> tables_from_pool(int n_tables, int rows_per_table, int pool_size, unsigned seed) {
  std::mt19937 random(seed);
  std::vector<Terms> pool(static_cast<size_t>(pool_size));
  for (Terms& row : pool) {
    const int n = 1 + int(random() % 6);
    for (int k = 0; k < n; ++k)
      row.emplace_back(int(random() % 500), random() % 5 == 0 ? 0.0 : 0.125 * (1 + random() % 7));
  }
  std::vector<StencilTable> tables(static_cast<size_t>(n_tables));
  for (StencilTable& t : tables) {
    t.n_base = 500;
    t.offsets.assign(1, 0);
    for (int r = 0; r < rows_per_table; ++r) {
      for (const auto& [index, weight] : pool[random() % pool.size()]) {
        t.indices.push_back(index);
        t.weights.push_back(weight);
      }
      t.offsets.push_back(int32_t(t.indices.size()));
    }
  }
  return tables;
}

Terms nonzero_terms(const StencilTable& t, int row) {
  Terms terms;
  for (int k = t.offsets[size_t(row)]; k < t.offsets[size_t(row) + 1]; ++k)
    if (t.weights[size_t(k)] != 0.0) terms.emplace_back(t.indices[size_t(k)], t.weights[size_t(k)]);
  return terms;
}

// Each distinct row once, where it first comes, found by an ordered map of the terms themselves.
void expect_merged_as_added_in_turn(const std::vector<StencilTable>& tables, bool colliding_keys) {
  std::vector<std::vector<size_t>> keys(tables.size());
  std::vector<const StencilTable*> table_pointers;
  std::vector<const std::vector<size_t>*> key_pointers;
  for (size_t t = 0; t < tables.size(); ++t) {
    for (int r = 0; r < tables[t].n_rows(); ++r) {
      const size_t key = StencilTableBuilder::row_key(tables[t], r);
      keys[t].push_back(colliding_keys ? key % 3 : key);  // rows of different terms under one key
    }
    table_pointers.push_back(&tables[t]);
    key_pointers.push_back(&keys[t]);
  }
  const int n_base = 500, first_row = 1024;
  const MergedStencilRows merged = merge_stencil_rows(table_pointers, key_pointers, n_base, first_row);

  std::map<Terms, int> row_of;
  std::vector<Terms> rows;
  for (size_t t = 0; t < tables.size(); ++t) {
    ASSERT_EQ(merged.points[t].size(), size_t(tables[t].n_rows()));
    for (int r = 0; r < tables[t].n_rows(); ++r) {
      const Terms terms = nonzero_terms(tables[t], r);
      const auto [at, added] = row_of.try_emplace(terms, int(rows.size()));
      if (added) rows.push_back(terms);
      ASSERT_EQ(merged.points[t][size_t(r)], first_row + at->second) << "table " << t << ", row " << r;
    }
  }
  EXPECT_EQ(merged.table.n_base, n_base);
  EXPECT_EQ(merged.table.first_row(), first_row);
  ASSERT_EQ(merged.table.n_rows(), int(rows.size()));
  for (int r = 0; r < merged.table.n_rows(); ++r) ASSERT_EQ(nonzero_terms(merged.table, r), rows[size_t(r)]);
  EXPECT_EQ(merged.table.indices.size(), size_t(merged.table.offsets.back())) << "no zero weight kept";
}

TEST(StencilRowsMerge, FewRowsMergeAsAddedInTurn) {
  expect_merged_as_added_in_turn(tables_from_pool(7, 40, 60, 1), false);
}

TEST(StencilRowsMerge, ManyRowsMergeAsAddedInTurnOnAllCores) {
  expect_merged_as_added_in_turn(tables_from_pool(40, 1500, 20000, 2), false);
}

TEST(StencilRowsMerge, RowsOfDifferentTermsUnderOneKeyStayApart) {
  expect_merged_as_added_in_turn(tables_from_pool(3, 20, 30, 3), true);
  expect_merged_as_added_in_turn(tables_from_pool(20, 1000, 3000, 4), true);
}

TEST(StencilRowsMerge, NoTablesOrNoRows) {
  expect_merged_as_added_in_turn({}, false);
  expect_merged_as_added_in_turn(tables_from_pool(3, 0, 1, 5), false);
}

}  // namespace
}  // namespace gps
