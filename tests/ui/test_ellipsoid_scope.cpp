// Whose ellipsoids the editor draws: all of them on a small mesh, on a large one those
// of the selection and its neighbours.
#include "ui/overlays/ellipsoid_scope.h"

#include <gtest/gtest.h>

#include "core/modelling/samples.h"

namespace gps {
namespace {

TEST(EllipsoidScope, AutomaticDrawsAllUpToTheLimitOnly) {
  EXPECT_TRUE(all_ellipsoids(EllipsoidScope::automatic, kAllEllipsoidsUpTo));
  EXPECT_FALSE(all_ellipsoids(EllipsoidScope::automatic, kAllEllipsoidsUpTo + 1));
  EXPECT_TRUE(all_ellipsoids(EllipsoidScope::all, 100000));
  EXPECT_FALSE(all_ellipsoids(EllipsoidScope::neighbourhood, 8));
}

TEST(EllipsoidScope, TheNeighbourhoodIsTheSelectionAndItsOneRing) {
  const CovarianceMesh cube = make_sample("cube");
  // Corner 6 = (1, 1, 1) shares an edge with the three corners that differ from it in one coordinate.
  std::vector<int> expected = {6};
  for (size_t v = 0; v < cube.n_vertices(); ++v)
    if ((cube.mean(v) - cube.mean(6)).norm() > 1.9 && (cube.mean(v) - cube.mean(6)).norm() < 2.1)
      expected.push_back(int(v));
  std::sort(expected.begin(), expected.end());
  ASSERT_EQ(expected.size(), 4u);
  EXPECT_EQ(selection_neighbourhood(cube, {6}), expected);
  EXPECT_TRUE(selection_neighbourhood(cube, {}).empty());
  EXPECT_EQ(selection_neighbourhood(cube, {6, 6, 99, -1}), expected) << "repeats and stray indices ignored";
  // Two opposite corners of a cube reach every vertex.
  const int opposite = [&] {
    for (size_t v = 0; v < cube.n_vertices(); ++v)
      if ((cube.mean(v) + cube.mean(6)).norm() < 1e-9) return int(v);
    return -1;
  }();
  EXPECT_EQ(selection_neighbourhood(cube, {6, opposite}).size(), 8u);
}

TEST(EllipsoidScope, OnTheLargeSphereTheNeighbourhoodIsSmall) {
  const CovarianceMesh sphere = make_sample("sphere", 100000);
  const std::vector<int> shown = selection_neighbourhood(sphere, {10, 20000});
  EXPECT_GE(shown.size(), 2u + 6u);
  EXPECT_LE(shown.size(), 2u + 8u);
  EXPECT_TRUE(std::is_sorted(shown.begin(), shown.end()));
}

}  // namespace
}  // namespace gps
