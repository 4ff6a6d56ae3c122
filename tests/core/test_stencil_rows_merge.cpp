#include "core/plans/stencil_rows_merge.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <tuple>
#include <utility>
#include <vector>

#include "core/plans/stencil_table.h"

namespace gps {
namespace {

using Terms = std::vector<std::pair<int, double>>;

// Tables whose rows are drawn from a pool, so that rows repeat within a table and across tables.
std::vector<StencilTable> tables_from_pool(int n_tables, int rows_per_table, int pool_size, unsigned seed) {
  std::mt19937 random(seed);
  std::vector<Terms> pool(static_cast<size_t>(pool_size));
  for (Terms& row : pool) {
    const int n = 1 + int(random() % 6);
    for (int k = 0; k < n; ++k) row.emplace_back(int(random() % 500), 0.125 * (1 + random() % 7));
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

Terms terms_of(const StencilTable& t, int row) {
  Terms terms;
  for (int k = t.offsets[size_t(row)]; k < t.offsets[size_t(row) + 1]; ++k)
    terms.emplace_back(t.indices[size_t(k)], t.weights[size_t(k)]);
  return terms;
}

// The rows the merge says it kept from the table the merge before made (`before`) have their terms
// there, in runs that go forward in both tables.
void expect_kept_rows_alike(const MergedStencilRows& merged, const StencilTable& before) {
  int end = 0, old_end = 0;
  for (const KeptStencilRows& run : merged.kept) {
    ASSERT_GT(run.count, 0);
    ASSERT_GE(run.first, end);
    ASSERT_GE(run.old_first, old_end);
    ASSERT_LE(run.first + run.count, merged.table.n_rows());
    ASSERT_LE(run.old_first + run.count, before.n_rows());
    for (int i = 0; i < run.count; ++i)
      ASSERT_EQ(terms_of(merged.table, run.first + i), terms_of(before, run.old_first + i)) << "kept row " << i;
    end = run.first + run.count;
    old_end = run.old_first + run.count;
  }
}

// Each distinct row once, where it first comes, found by an ordered map of the terms themselves.
// `firsts`: per table, what the merge before found of it (the table merged again), or none.
MergedStencilRows expect_merged_as_added_in_turn(const std::vector<StencilTable>& tables, bool colliding_keys,
                                                 std::vector<StencilRowFirsts>* firsts = nullptr) {
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
  std::vector<StencilRowFirsts*> first_pointers;
  if (firsts)
    for (StencilRowFirsts& f : *firsts) first_pointers.push_back(&f);
  MergedStencilRows merged = merge_stencil_rows(table_pointers, key_pointers, n_base, first_row, first_pointers);

  std::map<Terms, int> row_of;
  std::vector<Terms> rows;
  for (size_t t = 0; t < tables.size(); ++t) {
    EXPECT_EQ(merged.points[t].size(), size_t(tables[t].n_rows()));
    if (merged.points[t].size() != size_t(tables[t].n_rows())) return merged;
    for (int r = 0; r < tables[t].n_rows(); ++r) {
      const Terms terms = terms_of(tables[t], r);
      const auto [at, added] = row_of.try_emplace(terms, int(rows.size()));
      if (added) rows.push_back(terms);
      EXPECT_EQ(merged.points[t][size_t(r)], first_row + at->second) << "table " << t << ", row " << r;
    }
  }
  EXPECT_EQ(merged.table.n_base, n_base);
  EXPECT_EQ(merged.table.first_row(), first_row);
  EXPECT_EQ(merged.table.n_rows(), int(rows.size()));
  for (int r = 0; r < std::min(merged.table.n_rows(), int(rows.size())); ++r)
    EXPECT_EQ(terms_of(merged.table, r), rows[size_t(r)]) << "row " << r;
  EXPECT_EQ(merged.table.indices.size(), size_t(merged.table.offsets.back()));
  return merged;
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

// Tables merged again and again as a replanner merges its ranges: some kept (with what the merge
// before found of them), some gone, some new between them, some changed in place.
TEST(StencilRowsMerge, TablesMergedAgainFollowWhatTheLastMergeFound) {
  for (const auto& [rows_per_table, pool_size, colliding] :
       {std::tuple{30, 200, false}, std::tuple{600, 4000, false}, std::tuple{200, 300, true}}) {
    std::mt19937 random{unsigned(rows_per_table)};
    std::vector<StencilTable> tables = tables_from_pool(60, rows_per_table, pool_size, 7);
    std::vector<StencilRowFirsts> firsts(tables.size());
    MergedStencilRows before = expect_merged_as_added_in_turn(tables, colliding, &firsts);
    size_t kept_rows = 0;
    for (int round = 0; round < 12; ++round) {
      const std::vector<StencilTable> extra = tables_from_pool(4, rows_per_table, pool_size, unsigned(100 + round));
      for (int change = 0; change < 3; ++change) {
        const size_t at = random() % tables.size();
        switch (random() % 3) {
          case 0:  // a table gone
            tables.erase(tables.begin() + long(at));
            firsts.erase(firsts.begin() + long(at));
            break;
          case 1:  // a new one
            tables.insert(tables.begin() + long(at), extra[size_t(change)]);
            firsts.insert(firsts.begin() + long(at), StencilRowFirsts{});
            break;
          default:  // one changed in place: what was found of it is cleared
            tables[at] = extra[3];
            firsts[at] = {};
        }
      }
      SCOPED_TRACE(testing::Message() << rows_per_table << " rows per table, round " << round);
      MergedStencilRows merged = expect_merged_as_added_in_turn(tables, colliding, &firsts);
      expect_kept_rows_alike(merged, before.table);
      for (const KeptStencilRows& run : merged.kept) kept_rows += size_t(run.count);
      before = std::move(merged);
    }
    EXPECT_GT(kept_rows, size_t(0));  // most rounds follow the merge before
  }
}

TEST(StencilRowsMerge, NoTablesOrNoRows) {
  expect_merged_as_added_in_turn({}, false);
  expect_merged_as_added_in_turn(tables_from_pool(3, 0, 1, 5), false);
}

}  // namespace
}  // namespace gps
