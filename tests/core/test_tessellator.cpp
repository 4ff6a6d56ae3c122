#include "core/tessellator.h"

#include <gtest/gtest.h>

#include <map>

#include "core/error.h"
#include "core/stencil_table.h"
#include "tests/support/plan_fixture.h"

namespace gps {
namespace {

// Edges used by exactly one triangle.
int open_edges(const TriangleMesh& t) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& tri : t.triangles)
    for (int k = 0; k < 3; ++k) ++uses[{std::min(tri[size_t(k)], tri[size_t((k + 1) % 3)]), std::max(tri[size_t(k)], tri[size_t((k + 1) % 3)])}];
  int open = 0;
  for (const auto& [edge, n] : uses) open += n == 1;
  return open;
}

TEST(Tessellator, ClosedMeshesGiveClosedTriangleMeshes) {
  for (const char* name : {"cube", "wirecube", "cylinder", "torus", "pawn"}) {  // cylinder, pawn: T-junctions
    const test::PlannedMesh p(make_sample(name), 3);
    for (const int level : {1, 3, 8}) {
      const TriangleMesh t = tessellate(p.tables.plans, p.points, level);
      EXPECT_EQ(open_edges(t), 0) << name << " level " << level;
      // Same Euler characteristic as the base mesh: V − E + F with E = 3F/2.
      const int v = int(t.positions.size()), f = int(t.triangles.size());
      const auto& m = p.mesh.mesh;
      EXPECT_EQ(2 * v - f, 2 * (int(m.n_vertices()) - int(m.n_edges()) + int(m.n_faces()))) << name;
    }
  }
}

TEST(Tessellator, OpenMeshKeepsItsBoundaryAndNormalsPointOutward) {
  const test::PlannedMesh grid(make_sample("grid", 9), 3);
  const TriangleMesh t = tessellate(grid.tables.plans, grid.points, 4);
  EXPECT_EQ(open_edges(t), 4 * 3 * 4);  // the border: 4 sides × 3 patches × level 4
  const test::PlannedMesh cube(make_sample("cube"), 3);
  const TriangleMesh c = tessellate(cube.tables.plans, cube.points, 4);
  for (size_t i = 0; i < c.positions.size(); ++i) EXPECT_GT(c.normals[i].dot(c.positions[i]), 0.0);
  EXPECT_THROW(tessellate(cube.tables.plans, cube.points, 0), Error);
  EXPECT_THROW(tessellate(cube.tables.plans, cube.points, 65), Error);
}

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
