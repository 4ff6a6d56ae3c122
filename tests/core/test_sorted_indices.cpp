// sort_unique_indices: the indices sorted once each, whether it sorts them (few against the range) or
// flags them (many), as std::sort and std::unique give them.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "core/support/sorted_indices.h"

namespace gps {
namespace {

TEST(SortedIndices, SortsOnceEachBySortingOrByFlags) {
  std::mt19937 random(11);
  for (const int end : {1, 7, 64, 5000})
    for (const size_t count : {size_t(0), size_t(1), size_t(end) / 16, size_t(end) / 8, size_t(3 * end)}) {
      std::uniform_int_distribution<int> index(0, end - 1);
      std::vector<int> indices(count);
      for (int& i : indices) i = index(random);
      if (count > 0) indices.back() = end - 1;  // the last index, which a pass over the flags must reach
      std::vector<int> expected = indices;
      std::sort(expected.begin(), expected.end());
      expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
      sort_unique_indices(indices, end);
      EXPECT_EQ(indices, expected) << count << " indices below " << end;
    }
}

}  // namespace
}  // namespace gps
