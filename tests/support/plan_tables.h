#pragma once
// Plan tables compared exactly: every array of two SurfaceTables, bit for bit (the re-planners' tests).
#include <gtest/gtest.h>

#include <string>

#include "core/plans/plan_builder.h"

namespace gps::test {

/// Re-planners' ranges of a few faces in tests, so that a change leaves most of them as they were.
constexpr int kSmallRanges = 8;

inline void expect_same_tables(const SurfaceTables& a, const SurfaceTables& b, const std::string& where) {
  const PatchPlans &p = a.plans, &q = b.plans;
  EXPECT_EQ(p.shape, q.shape) << where;
  EXPECT_EQ(p.max_depth, q.max_depth) << where;
  EXPECT_EQ(p.nodes, q.nodes) << where;
  EXPECT_EQ(p.patch_roots, q.patch_roots) << where;
  EXPECT_EQ(p.patch_corner_points, q.patch_corner_points) << where;
  EXPECT_EQ(p.patch_edges, q.patch_edges) << where;
  EXPECT_EQ(p.patch_neighbours, q.patch_neighbours) << where;
  EXPECT_EQ(p.corner_owners, q.corner_owners) << where;
  EXPECT_EQ(p.extraordinary_tables, q.extraordinary_tables) << where;  // doubles compared exactly
  EXPECT_EQ(a.stencils.n_base, b.stencils.n_base) << where;
  EXPECT_EQ(a.stencils.row_gap, b.stencils.row_gap) << where;
  EXPECT_EQ(a.stencils.offsets, b.stencils.offsets) << where;
  EXPECT_EQ(a.stencils.indices, b.stencils.indices) << where;
  EXPECT_EQ(a.stencils.weights, b.stencils.weights) << where;
}

}  // namespace gps::test
