#include "core/plans/stencil_table.h"

#include <gtest/gtest.h>

#include <tuple>
#include <vector>

#include "core/mesh/dual_map.h"
#include "core/plans/planned_surface.h"
#include "core/modelling/samples.h"
#include "tests/support/plan_fixture.h"

namespace gps {
namespace {

// After an edit of k vertices, re-applying only the dependent rows equals the full product (small
// edits of a large table take the sparse paths, large ones re-apply the whole table).
// Parameters: sample, size, changed vertices, whether the edit is small enough for a sparse path.
class StencilTable : public testing::TestWithParam<std::tuple<const char*, int, std::vector<int>, bool>> {};

INSTANTIATE_TEST_SUITE_P(Edits, StencilTable,
                         testing::Values(std::tuple{"valence6", 0, std::vector<int>{0, 5, 17}, false},
                                         std::tuple{"sphere", 2000, std::vector<int>{3}, true},
                                         std::tuple{"sphere", 2000, std::vector<int>{0, 1, 2, 700, 1500}, false},
                                         std::tuple{"icosphere", 1280, std::vector<int>{0, 1, 20}, true}));

TEST_P(StencilTable, IncrementalUpdateEqualsFullApply) {
  const auto& [name, size, changed, sparse] = GetParam();
  test::PlannedMesh p(make_sample(name, size), 4);
  const auto deps = stencil_dependents(p.tables.stencils);
  size_t n_dependents = 0;
  for (const int v : changed) n_dependents += size_t(deps.offsets[size_t(v) + 1] - deps.offsets[size_t(v)]);
  EXPECT_GT(n_dependents, 0u);
  EXPECT_EQ(4 * n_dependents < size_t(p.tables.stencils.n_rows()), sparse)
      << "the update path this case is meant to take";
  std::vector<Dual> points = p.points;
  for (const int v : changed) {
    Mat3 c = p.mesh.covariance(size_t(v));
    c(0, 0) *= 0.01;
    points[size_t(v)] = p.base[size_t(v)] = to_dual(p.mesh.mean(size_t(v)) + Vec3(0.1, 0.2, 0.3), c);
  }
  update_stencils(p.tables.stencils, deps, changed, points);
  const auto full = apply_stencils(p.tables.stencils, p.base);
  ASSERT_EQ(points.size(), full.size());
  for (size_t i = 0; i < full.size(); ++i) EXPECT_LT((points[i] - full[i]).norm(), 1e-12 * (1 + full[i].norm())) << i;
  EXPECT_NE(points, p.points);
}

// The planned surface's own update after an edit equals a planned surface built anew from the
// edited mesh, for Catmull-Clark and Loop, and its rows_reading lists exactly the rows whose points
// the edit changed (every other row keeps its value bit for bit).
class PlannedSurfaceUpdate : public testing::TestWithParam<std::tuple<const char*, int, std::vector<int>>> {};

INSTANTIATE_TEST_SUITE_P(Edits, PlannedSurfaceUpdate,
                         testing::Values(std::tuple{"valence5", 0, std::vector<int>{0}},
                                         std::tuple{"pawn", 0, std::vector<int>{0, 40, 300}},
                                         std::tuple{"icosphere", 320, std::vector<int>{1, 7}},
                                         std::tuple{"sphere", 2000, std::vector<int>{3, 1500}}));

TEST_P(PlannedSurfaceUpdate, EqualsASurfacePlannedAnewAndChangesOnlyTheRowsItLists) {
  const auto& [name, size, changed] = GetParam();
  const CovarianceMesh mesh = make_sample(name, size);
  PlannedSurface surface(mesh, PlanOptions{});
  const std::vector<Dual> before = surface.points();
  CovarianceMesh edited = mesh;
  for (const int v : changed) {
    Mat3 c = mesh.covariance(size_t(v));
    c(0, 0) *= 0.01;
    edited.set_covariance(size_t(v), c);
    edited.set_mean(size_t(v), mesh.mean(size_t(v)) + Vec3(0.1, 0.2, 0.3));
  }
  surface.update(edited, changed);
  const PlannedSurface anew(edited, PlanOptions{});
  ASSERT_EQ(surface.points().size(), anew.points().size());
  for (size_t i = 0; i < anew.points().size(); ++i)
    EXPECT_LT((surface.points()[i] - anew.points()[i]).norm(), 1e-12 * (1 + anew.points()[i].norm())) << i;
  const std::vector<int> rows = surface.rows_reading(changed);
  ASSERT_FALSE(rows.empty());
  const int first_row = surface.tables().stencils.first_row();
  std::vector<bool> listed(before.size(), false);
  for (const int v : changed) listed[size_t(v)] = true;
  for (const int r : rows) listed[size_t(first_row + r)] = true;
  for (size_t i = 0; i < before.size(); ++i) {
    if (!listed[i]) {
      EXPECT_EQ(surface.points()[i], before[i]) << "point " << i << " changed but is not listed";
    }
  }
}

}  // namespace
}  // namespace gps
