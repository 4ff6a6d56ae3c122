// Thin Gaussians on the GPU: the torus, turned off the axes, with discs (thin along the surface normal)
// or needles (long along it), evaluated by the GPU at its tessellation vertices against the CPU
// evaluator at the same (patch, u, v). Σ⁻¹ is inverted in double before its upload
// (render/pipeline/plan_buffers.cpp): inverted in float, a needle of condition 1e5 lost its thin
// directions and the surface spiked out of the frame.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "core/evaluation/patch_eval.h"
#include "core/mesh/samples.h"
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
};

// Every GPU tessellation vertex against the CPU evaluator; positions relative to the diagonal. A
// vertex where the CPU's own back map is degenerate (no positive definite q̂, or tangents nearly
// parallel) is counted apart.
Errors compare(const CovarianceMesh& mesh, float level) {
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh);
  DrawOptions o;
  o.level = level;
  const auto vertices = renderer.capture_vertices(Camera{}, o, 512, 512);
  const test::PlannedMesh cpu(mesh, PlanOptions{});
  const double diag = bounding_box_diagonal(mesh);
  Errors e;
  for (const auto& v : vertices) {
    const auto s = evaluate_patch(cpu.tables.plans, cpu.points, int(v.evaluated[0]), v.evaluated[1], v.evaluated[2]);
    if (!s || s->du.cross(s->dv).norm() < 1e-6 * s->du.norm() * s->dv.norm()) {
      ++e.degenerate;
      continue;
    }
    const Vec3 position(v.position[0], v.position[1], v.position[2]), normal(v.normal[0], v.normal[1], v.normal[2]);
    const bool finite = position.allFinite() && normal.allFinite();
    e.position = std::max(e.position, finite ? (s->position - position).norm() / diag : 1.0);
    const double c = std::clamp(s->normal.dot(normal.normalized()), -1.0, 1.0);
    e.normal_degrees = std::max(e.normal_degrees, finite ? std::acos(c) * 180.0 / M_PI : 180.0);
    ++e.count;
  }
  return e;
}

// Condition numbers 1e4 and 1e5 (σ ratio 100 and 316) for discs and needles, 1e8 (σ ratio 1e4) for
// discs: positions and normals within float precision of the CPU's. Beyond (needles of 1e8, any
// Gaussian of 1e12) float sums of 9D points no longer hold Σ⁻¹'s thin directions (docs/design.md).
TEST_F(NeedleCovariances, MatchTheCpuEvaluator) {
  const std::vector<std::pair<double, bool>> cases = {{1e2, false}, {std::sqrt(1e5), false}, {1e4, false},
                                                      {1e2, true},  {std::sqrt(1e5), true}};
  for (const auto& [ratio, needle] : cases)
    for (const float level : {1.0f, 7.0f}) {
      const Errors e = compare(thin_torus(ratio, needle), level);
      std::printf("%-6s condition %.0e level %2.0f: position %.1e of the diagonal, normal %.4f degrees, %zu vertices, "
                  "%zu degenerate\n",
                  needle ? "needle" : "disc", ratio * ratio, level, e.position, e.normal_degrees, e.count,
                  e.degenerate);
      EXPECT_GT(e.count, size_t(1000));
      EXPECT_LT(e.position, 5e-6) << (needle ? "needle" : "disc") << " condition " << ratio * ratio;
      EXPECT_LT(e.normal_degrees, 0.01) << (needle ? "needle" : "disc") << " condition " << ratio * ratio;
    }
}

}  // namespace
}  // namespace gps
