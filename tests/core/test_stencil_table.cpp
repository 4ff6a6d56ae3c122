#include "core/stencil_table.h"

#include <gtest/gtest.h>

#include <tuple>
#include <vector>

#include "core/dual_map.h"
#include "core/samples.h"
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
                                         std::tuple{"grid", 400, std::vector<int>{0, 1, 20}, true}));

TEST_P(StencilTable, IncrementalUpdateEqualsFullApply) {
  const auto& [name, size, changed, sparse] = GetParam();
  test::PlannedMesh p(make_sample(name, size), 4);
  const auto deps = stencil_dependents(p.tables.stencils);
  size_t n_dependents = 0;
  for (const int v : changed) n_dependents += size_t(deps.offsets[size_t(v) + 1] - deps.offsets[size_t(v)]);
  EXPECT_GT(n_dependents, 0u);
  EXPECT_EQ(4 * n_dependents < size_t(p.tables.stencils.n_rows()), sparse) << "the update path this case is meant to take";
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

}  // namespace
}  // namespace gps
