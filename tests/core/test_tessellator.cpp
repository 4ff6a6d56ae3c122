#include "core/evaluation/tessellator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "core/mesh/inference.h"
#include "core/support/error.h"
#include "tests/support/plan_fixture.h"

namespace gps {
namespace {

// Edges used by exactly one triangle.
int open_edges(const TriangleMesh& t) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& tri : t.triangles)
    for (int k = 0; k < 3; ++k)
      ++uses[{std::min(tri[size_t(k)], tri[size_t((k + 1) % 3)]), std::max(tri[size_t(k)], tri[size_t((k + 1) % 3)])}];
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
      const CovarianceMesh& m = p.mesh;
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

// A flat square twice, back to back, its centres two vertices in one place: Loop's limit surface has no
// tangent plane where the sheets meet, and the vertices there take their triangles' normal. Every
// normal written is a unit vector (glTF requires it).
TEST(Tessellator, EveryNormalIsAUnitVectorWhereTheSurfaceHasNoTangentPlane) {
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0}, {0.5, 0.5, 0}};
  const std::vector<std::vector<int>> faces = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4},
                                               {1, 0, 5}, {2, 1, 5}, {3, 2, 5}, {0, 3, 5}};
  CovarianceMesh mesh = make_covariance_mesh(p, std::vector<Mat3>(p.size(), Mat3::Identity()), faces, "two sheets");
  infer_covariances(mesh);
  const test::PlannedMesh planned(mesh, PlanOptions{Scheme::loop});
  for (const int level : {2, 5}) {
    const TriangleMesh t = tessellate(planned.tables.plans, planned.points, level);
    for (size_t i = 0; i < t.normals.size(); ++i)
      EXPECT_NEAR(t.normals[i].norm(), 1.0, 1e-12) << "level " << level << " vertex " << i;
  }
}

TEST(Tessellator, ReportsTheSharesOfPatchesDoneAndStopsWhenAsked) {
  for (const char* name : {"torus", "icosphere"}) {  // quad and triangle patches
    const test::PlannedMesh p(make_sample(name), 3);
    const int patches = p.tables.plans.n_patches();
    std::vector<double> fractions;
    const TriangleMesh t = tessellate(p.tables.plans, p.points, 3, [&](double f) {
      fractions.push_back(f);
      return true;
    });
    EXPECT_EQ(t.triangles.size(), tessellate(p.tables.plans, p.points, 3).triangles.size()) << name;
    ASSERT_FALSE(fractions.empty()) << name;
    EXPECT_EQ(fractions[0], 0.0) << name;
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end())) << name;
    EXPECT_LT(fractions.back(), 1.0) << name;
    const int every = std::max(1, patches / 100);
    EXPECT_EQ(int(fractions.size()), (patches + every - 1) / every) << name << ": " << patches << " patches";

    int calls = 0;
    EXPECT_THROW(tessellate(p.tables.plans, p.points, 3, [&](double) { return ++calls < 2; }), Cancelled) << name;
    EXPECT_EQ(calls, 2) << name;
  }
}

}  // namespace
}  // namespace gps
