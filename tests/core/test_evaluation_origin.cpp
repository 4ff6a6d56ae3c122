// The CPU evaluates a mesh far from the origin about its evaluation origin: its surface is then the
// one of the same mesh near the origin, moved, to the digits double holds (it spiked by a quarter
// of its size when a pawn a millionth the size lay 1.3e8 away).
#include <gtest/gtest.h>

#include <cmath>

#include "core/evaluation/surface_samples.h"
#include "core/modelling/samples.h"
#include "core/reference/reference_subdivision.h"

namespace gps {
namespace {

constexpr double kScale = 0x1p-20, kOffset = 0x1p27;

// A mesh moved to `offset` at `scale`, and the same mesh in the near frame recovered from it exactly
// (a difference of doubles within a factor 2 of each other, and powers of 2): the two are related by
// x ↦ x·scale + offset without a rounding.
struct FarAndNear {
  CovarianceMesh far, near;
};

FarAndNear far_and_near(const char* name) {
  FarAndNear m{make_sample(name), make_sample(name)};
  for (size_t v = 0; v < m.far.n_vertices(); ++v) {
    const Vec3 far = m.near.mean(v) * kScale + Vec3(kOffset, 0, 0);
    m.far.set_mean(v, far);
    m.far.set_covariance(v, m.near.covariance(v) * (kScale * kScale));
    m.near.set_mean(v, (far - Vec3(kOffset, 0, 0)) / kScale);
  }
  return m;
}

double max_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double d = 0;
  for (size_t i = 0; i < a.size(); ++i) d = std::max(d, (a[i] - b[i]).norm());
  return d;
}

TEST(EvaluationOrigin, IsTheOriginForAMeshNearItAndTheCentreForOneFarAway) {
  const FarAndNear m = far_and_near("pawn");
  EXPECT_TRUE(evaluation_origin(m.near).isZero());
  EXPECT_TRUE(evaluation_origin(make_sample("pawn")).isZero());  // ordinary meshes evaluate as they did
  const Vec3 origin = evaluation_origin(m.far);
  EXPECT_NEAR(origin.x(), kOffset, 1e-5);
  EXPECT_EQ(base_points(m.near), base_points(m.near, Vec3::Zero()));
}

TEST(EvaluationOrigin, APlannedSurfaceFarAwayIsTheNearOneMovedToTheDigitsDoubleHolds) {
  for (const char* name : {"pawn", "cube", "icosphere"}) {  // quads and triangles, Catmull-Clark and Loop
    const FarAndNear m = far_and_near(name);
    const PlannedSurface far(m.far, PlanOptions{}), near(m.near, PlanOptions{});
    const double size = bounding_box_diagonal(m.near) * kScale;
    // About the far surface's origin, where its points are.
    const TriangleMesh about = tessellate(far.tables().plans, far.points(), 4);
    TriangleMesh expected = tessellate(near, 4);
    const Vec3 shift = Vec3(kOffset, 0, 0) - far.origin();
    for (Vec3& p : expected.positions) p = p * kScale + shift;
    ASSERT_EQ(about.positions.size(), expected.positions.size()) << name;
    EXPECT_LT(max_distance(about.positions, expected.positions), 1e-9 * size) << name;
    EXPECT_LT(max_distance(about.normals, expected.normals), 1e-7) << name;
    // Moved back, the positions are those to the spacing of doubles at 1.3e8 (2^-25).
    const TriangleMesh world = tessellate(far, 4);
    for (Vec3& p : expected.positions) p += far.origin();
    EXPECT_LE(max_distance(world.positions, expected.positions), 0x1p-24) << name;
    const auto sample = evaluate_patch(far, 0, 0.3, 0.2), sample_near = evaluate_patch(near, 0, 0.3, 0.2);
    ASSERT_TRUE(sample && sample_near) << name;
    EXPECT_LE((sample->position - (sample_near->position * kScale + Vec3(kOffset, 0, 0))).norm(), 0x1p-24) << name;
  }
}

TEST(EvaluationOrigin, TheReferenceSubdivisionFarAwayIsTheNearOneMoved) {
  const FarAndNear m = far_and_near("pawn");
  const SubdivisionOptions options{Scheme::catmull_clark, 2, true, LoopBeta::loop, true};
  const SubdivisionResult far = subdivide(m.far, options), near = subdivide(m.near, options);
  ASSERT_EQ(far.mesh.n_vertices(), near.mesh.n_vertices());
  std::vector<Vec3> moved(near.mesh.n_vertices()), far_means(far.mesh.n_vertices());
  for (size_t v = 0; v < moved.size(); ++v) {
    moved[v] = near.mesh.mean(v) * kScale + Vec3(kOffset, 0, 0);
    far_means[v] = far.mesh.mean(v);
  }
  EXPECT_LE(max_distance(far_means, moved), 0x1p-24);
  EXPECT_LT(max_distance(far.normals, near.normals), 1e-7);
}

}  // namespace
}  // namespace gps
