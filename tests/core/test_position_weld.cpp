// Welding positions (core/io/position_weld.h): the clusters a brute-force single linkage gives, each
// named by its lowest index, for scattered, crowded and coincident points.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "core/io/position_weld.h"
#include "core/support/disjoint_sets.h"

namespace gps {
namespace {

std::vector<int> brute_force_roots(const std::vector<Vec3>& p, double tolerance) {
  LowestRootSets sets(p.size());
  for (size_t a = 0; a < p.size(); ++a)
    for (size_t b = a + 1; b < p.size(); ++b)
      if (p[a] == p[b] || (p[a] - p[b]).norm() <= tolerance) sets.unite(int(a), int(b));
  std::vector<int> roots(p.size());
  for (size_t v = 0; v < p.size(); ++v) roots[v] = sets.find(int(v));
  return roots;
}

TEST(PositionWeld, EqualPositionsAreOneAndMinusZeroIsZero) {
  const std::vector<Vec3> p = {{1, 2, 3}, {0, 0, 0}, {1, 2, 3}, {-0.0, 0, -0.0}, {1, 2, 3 + 1e-15}};
  EXPECT_EQ(weld_roots(p, 0), (std::vector<int>{0, 1, 0, 1, 4}));
  EXPECT_TRUE(weld_roots({}, 0.1).empty());
}

TEST(PositionWeld, ChainsWithinTheToleranceJoin) {
  // 0.9 apart in a line: each within 1 of the next, the ends 3.6 apart, all one cluster; a point
  // 1.1 beyond the last stays apart.
  std::vector<Vec3> p;
  for (int i = 4; i >= 0; --i) p.push_back(Vec3(0.9 * i, 0, 0));
  p.push_back(Vec3(-1.1, 0, 0));
  EXPECT_EQ(weld_roots(p, 1.0), (std::vector<int>{0, 0, 0, 0, 0, 5}));
}

TEST(PositionWeld, EqualsBruteForceSingleLinkage) {
  std::mt19937 random(7);
  for (const double spread : {1.0, 0.05, 1e-3}) {
    std::uniform_real_distribution<double> coordinate(-spread, spread);
    std::vector<Vec3> p;
    for (int i = 0; i < 600; ++i) {
      p.push_back(Vec3(coordinate(random), coordinate(random), coordinate(random)));
      if (i % 7 == 0) p.push_back(p[size_t(random() % p.size())]);  // exact duplicates too
    }
    for (const double tolerance : {0.0, 1e-3, 0.02, 0.1})
      EXPECT_EQ(weld_roots(p, tolerance), brute_force_roots(p, tolerance)) << spread << " " << tolerance;
  }
}

}  // namespace
}  // namespace gps
