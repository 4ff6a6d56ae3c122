// Thin Gaussians on the GPU: the torus, turned off the axes, with discs (thin along the surface normal)
// or needles (long along it), evaluated by the GPU at its tessellation vertices against the CPU
// evaluator at the same (patch, u, v). Σ⁻¹ is inverted in double before its upload
// (render/pipeline/plan_buffers.cpp): inverted in float, a needle of condition 1e5 lost its thin
// directions and the surface spiked out of the frame. Past condition 1e6 the GPU keeps the mesh's
// plan points in double (render/gl/point_precision.h).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "core/evaluation/patch_eval.h"
#include "core/modelling/samples.h"
#include "render/gl/point_precision.h"
#include "render/pipeline/surface_renderer.h"
#include "tests/support/gl_fixture.h"
#include "tests/support/plan_fixture.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

using NeedleCovariances = test::GlTest;
using test::thin_torus;

struct Errors {
  double position = 0, normal_degrees = 0;
  size_t count = 0, degenerate = 0;
  PointPrecision precision = PointPrecision::single_float;  // the renderer's
};

// Every GPU tessellation vertex against the CPU evaluator given the mesh in the renderer's frame, as
// the GPU is (render/gl/normalised_frame.h); positions relative to the diagonal. At condition
// 1e12 the CPU's own surface moves with the frame it is given (by 3.5e-6 of the diagonal and 0.011°
// between the world's and the normalised one): its doubles are the GPU's reference. A vertex where
// the CPU's own back map is degenerate (no positive definite q̂, or tangents nearly parallel) is
// counted apart.
Errors compare(const CovarianceMesh& mesh, float level) {
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh);
  DrawOptions o;
  o.level = level;
  const auto vertices = renderer.capture_vertices(Camera{}, o, 512, 512);
  const test::PlannedMesh cpu(renderer.frame().to_frame(mesh), PlanOptions{});
  const double diag = bounding_box_diagonal(mesh);
  Errors e;
  e.precision = renderer.point_precision();
  for (const auto& v : vertices) {
    const auto s = evaluate_patch(cpu.tables.plans, cpu.points, int(v.evaluated[0]), v.evaluated[1], v.evaluated[2]);
    if (!s || s->du.cross(s->dv).norm() < 1e-6 * s->du.norm() * s->dv.norm()) {
      ++e.degenerate;
      continue;
    }
    const Vec3 position(v.position[0], v.position[1], v.position[2]), normal(v.normal[0], v.normal[1], v.normal[2]);
    const glm::dvec3 world = renderer.frame().to_world(glm::dvec3(s->position.x(), s->position.y(), s->position.z()));
    const bool finite = position.allFinite() && normal.allFinite();
    e.position = std::max(e.position, finite ? (Vec3(world.x, world.y, world.z) - position).norm() / diag : 1.0);
    const double c = std::clamp(s->normal.dot(normal.normalized()), -1.0, 1.0);
    e.normal_degrees = std::max(e.normal_degrees, finite ? std::acos(c) * 180.0 / M_PI : 180.0);
    ++e.count;
  }
  return e;
}

// Condition numbers 1e4 and 1e5 (σ ratio 100 and 316) for discs and needles in float points; 1e8 (σ
// ratio 1e4) and 1e12 (σ ratio 1e6) for both in double ones, where float sums of 9D points no longer
// hold a needle's thin directions (docs/design.md): positions and normals within float precision of
// the CPU's.
TEST_F(NeedleCovariances, MatchTheCpuEvaluator) {
  const std::vector<std::pair<double, bool>> cases = {{1e2, false}, {std::sqrt(1e5), false}, {1e4, false}, {1e6, false},
                                                      {1e2, true},  {std::sqrt(1e5), true},  {1e4, true},  {1e6, true}};
  for (const auto& [ratio, needle] : cases)
    for (const float level : {1.0f, 7.0f}) {
      const Errors e = compare(thin_torus(ratio, needle), level);
      std::printf(
          "%-6s condition %.0e level %2.0f: position %.1e of the diagonal, normal %.4f degrees, %zu vertices, "
          "%zu degenerate, %s points\n",
          needle ? "needle" : "disc", ratio * ratio, level, e.position, e.normal_degrees, e.count, e.degenerate,
          e.precision == PointPrecision::double_float ? "double" : "float");
      EXPECT_GT(e.count, size_t(1000));
      EXPECT_EQ(e.precision,
                ratio * ratio > kDoublePointsCondition ? PointPrecision::double_float : PointPrecision::single_float);
      EXPECT_LT(e.position, 5e-6) << (needle ? "needle" : "disc") << " condition " << ratio * ratio;
      EXPECT_LT(e.normal_degrees, 0.01) << (needle ? "needle" : "disc") << " condition " << ratio * ratio;
    }
}

// An edit that makes one Gaussian a needle of condition 1e12 takes the mesh to double points, and
// one that makes it round again back to float: the surface as a renderer given the edited mesh
// draws it, bit for bit.
TEST_F(NeedleCovariances, AnEditChangesThePrecision) {
  const CovarianceMesh round = thin_torus(10.0, true), needles = thin_torus(1e6, true);
  CovarianceMesh edited = round;
  edited.set_covariance(0, needles.covariance(0));
  const auto draw = [](SurfaceRenderer& renderer) {
    DrawOptions o;
    o.level = 4.0f;
    std::vector<float> values;
    for (const auto& v : renderer.capture_vertices(Camera{}, o, 256, 256))
      values.insert(values.end(), {v.position[0], v.position[1], v.position[2], v.normal[0], v.normal[1], v.normal[2]});
    return values;
  };
  SurfaceRenderer renderer, fresh;
  renderer.set_mesh(round);
  ASSERT_EQ(renderer.point_precision(), PointPrecision::single_float);
  renderer.update_vertices(edited, {0});
  EXPECT_EQ(renderer.point_precision(), PointPrecision::double_float);
  fresh.set_mesh(edited, PlannedSurface(edited, PlanOptions{}), renderer.frame());
  EXPECT_EQ(draw(renderer), draw(fresh));
  renderer.update_vertices(round, {0});
  EXPECT_EQ(renderer.point_precision(), PointPrecision::single_float);
  fresh.set_mesh(round, PlannedSurface(round, PlanOptions{}), renderer.frame());
  EXPECT_EQ(draw(renderer), draw(fresh));
}

// The precision followed through edits of many Gaussians at once (assessed on all cores) and of a
// few: a needle among 20,000 round Gaussians takes the mesh to double, in an edit of all of them, of
// some, or of the needle alone, and rounding the last needle takes it back to float.
TEST(MeshPointPrecision, FollowsEditsOfManyGaussiansAndOfFew) {
  const Mat3 needle = Vec3(1.0, 1e-7, 1e-7).asDiagonal();
  FramedGaussians g;
  g.means.assign(20000, Vec3::Zero());
  g.covariances.assign(20000, 0.01 * Mat3::Identity());
  std::vector<int> all(g.n_vertices()), some;
  for (int v = 0; v < int(all.size()); ++v) {
    all[size_t(v)] = v;
    if (v % 3 == 0) some.push_back(v);
  }
  MeshPointPrecision precision(g);
  EXPECT_EQ(precision.precision(), PointPrecision::single_float);
  g.covariances[19998] = needle;
  precision.update(g, all);
  EXPECT_EQ(precision.precision(), PointPrecision::double_float);
  g.covariances[19998] = 0.01 * Mat3::Identity();
  g.covariances[19995] = needle;
  precision.update(g, some);  // 19998 is not among them: still a needle to the precision
  EXPECT_EQ(precision.precision(), PointPrecision::double_float);
  precision.update(g, {19998});
  EXPECT_EQ(precision.precision(), PointPrecision::double_float);  // vertex 19995 is one now
  g.covariances[19995] = 0.01 * Mat3::Identity();
  precision.update(g, some);
  EXPECT_EQ(precision.precision(), PointPrecision::single_float);
  // After a change of topology: the needle carried to where its vertex went, then assessed again.
  g.covariances[7] = needle;
  precision.update(g, {7});
  std::vector<int> origin(all.rbegin(), all.rend());  // the vertices in reverse order
  FramedGaussians reversed;
  reversed.means = g.means;
  reversed.covariances.assign(g.covariances.rbegin(), g.covariances.rend());
  const MeshPointPrecision carried(precision, reversed, origin, {});
  EXPECT_EQ(carried.precision(), PointPrecision::double_float);
  reversed.covariances[g.n_vertices() - 8] = 0.01 * Mat3::Identity();
  EXPECT_EQ(MeshPointPrecision(precision, reversed, origin, all).precision(), PointPrecision::single_float);
  EXPECT_EQ(MeshPointPrecision(reversed).precision(), PointPrecision::single_float);
}

// After a change that keeps vertex numbers, from its changed Gaussians alone (render/gl/gaussians_change.h):
// a new vertex that did not change has its origin's need, a changed one is assessed, and a needle
// rounded takes the mesh back to float.
TEST(MeshPointPrecision, FollowsAChangeThatKeepsVertexNumbers) {
  const Mat3 needle = Vec3(1.0, 1e-7, 1e-7).asDiagonal(), round = 0.01 * Mat3::Identity();
  FramedGaussians g;
  g.means.assign(10, Vec3::Zero());
  g.covariances.assign(10, round);
  g.covariances[3] = needle;
  const MeshPointPrecision before(g);
  ASSERT_EQ(before.precision(), PointPrecision::double_float);
  // Vertex 3 rounded, a new vertex 10 from it unchanged (a needle still), a new vertex 11 of its own.
  std::vector<int> origin{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 3, -1};
  GaussiansChange change;
  change.n_vertices = 12;
  change.changed = {3, 11};
  change.covariances = {round, round};
  change.means = {Vec3::Zero(), Vec3::Zero()};
  EXPECT_EQ(MeshPointPrecision(before, change, origin).precision(), PointPrecision::double_float) << "vertex 10";
  origin[10] = 2;
  EXPECT_EQ(MeshPointPrecision(before, change, origin).precision(), PointPrecision::single_float);
  // A changed vertex made a needle, the others as they were; and the new vertices removed.
  change.covariances = {needle, round};
  origin[10] = 2;
  EXPECT_EQ(MeshPointPrecision(before, change, origin).precision(), PointPrecision::double_float) << "vertex 3";
  GaussiansChange removed;
  removed.n_vertices = 3;  // vertex 3 gone
  EXPECT_EQ(MeshPointPrecision(before, removed, {0, 1, 2}).precision(), PointPrecision::single_float);
}

}  // namespace
}  // namespace gps
