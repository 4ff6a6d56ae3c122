// The corner pass (render/pipeline/corner_limit_pass.h) against the CPU evaluator: each slot holds its
// corner's limit point and normal where it evaluates the corner (its owner, or every patch at a corner
// whose patches have normals of their own), and the limit point halfway along the edge that starts
// there where that edge names its limit curve (curve_edge), which the adaptive levels read from that
// slot; zero everywhere else. On quad, mixed (split faces beside whole quads), triangle, open and
// creased meshes.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "core/evaluation/patch_eval.h"
#include "core/modelling/samples.h"
#include "core/plans/patch_adjacency.h"
#include "render/pipeline/surface_renderer.h"
#include "tests/support/gl_fixture.h"
#include "tests/support/patch_edge_point.h"
#include "tests/support/plan_fixture.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

using CornerPass = test::GlTest;

bool zero(const float* v, int n) {
  for (int i = 0; i < n; ++i)
    if (v[i] != 0.0f) return false;
  return true;
}

double distance(const float* v, const Vec3& x) { return (Vec3(v[0], v[1], v[2]) - x).norm(); }

// The renderer's corner pass for `mesh`, slot by slot, against the CPU's plans evaluated in its frame.
void expect_corner_pass(const std::string& name, const CovarianceMesh& mesh, Scheme scheme) {
  PlanOptions options;
  options.scheme = scheme;
  const NormalisedFrame frame = NormalisedFrame::of(mesh);
  const test::PlannedMesh cpu(frame.to_frame(mesh), options);
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh, cpu.tables, frame);
  const PatchPlans& plans = cpu.tables.plans;
  const int n = plans.corners(), slots = n * plans.n_patches();
  const std::vector<float> pass = renderer.read_corner_pass();
  ASSERT_EQ(pass.size(), size_t(12 * slots)) << name;
  int corners = 0, midpoints = 0, sharp = 0;
  for (int p = 0; p < plans.n_patches(); ++p)
    for (int c = 0; c < n; ++c) {
      const int slot = n * p + c;
      const float* limit = &pass[size_t(8 * slot)];
      const float* midpoint = &pass[size_t(8 * slots + 4 * slot)];
      const std::string where = name + " patch " + std::to_string(p) + " corner " + std::to_string(c);
      const CornerOwner owner = corner_owner(plans, p, c);
      if ((owner.patch == p && owner.corner == c) || owner.sharp) {
        sharp += owner.sharp;
        ++corners;
        const auto [u, v] = test::edge_point(plans.shape, c, 0.0);
        const auto s = evaluate_patch(plans, cpu.points, p, u, v);
        ASSERT_TRUE(s.has_value()) << where;
        EXPECT_LT(distance(limit, s->position), 1e-4) << where << ": corner";
        EXPECT_LT(distance(limit + 4, s->normal), 1e-3) << where << ": normal";
      } else {
        EXPECT_TRUE(zero(limit, 8)) << where << ": a corner it does not evaluate";
      }
      if (curve_edge(plans, p, c) == PatchEdgeSlot{p, c}) {
        ++midpoints;
        const auto [u, v] = test::edge_point(plans.shape, c, 0.5);
        const auto s = evaluate_patch(plans, cpu.points, p, u, v);
        ASSERT_TRUE(s.has_value()) << where;
        EXPECT_LT(distance(midpoint, s->position), 1e-4) << where << ": midpoint";
        EXPECT_EQ(midpoint[3], 0.0f) << where;
      } else {
        EXPECT_TRUE(zero(midpoint, 4)) << where << ": a midpoint another edge holds";
      }
    }
  EXPECT_GT(corners, 0) << name;
  EXPECT_EQ(sharp > 0, !mesh.sharpness.empty()) << name << ": corners with normals of their own";
  EXPECT_GT(midpoints, slots / 4) << name;
}

TEST_F(CornerPass, HoldsEachCornerAndCurveMidpointAtTheSlotThatNamesIt) {
  expect_corner_pass("cube", make_sample("cube"), Scheme::catmull_clark);
  expect_corner_pass("pawn", make_sample("pawn"), Scheme::catmull_clark);          // split faces beside quads
  expect_corner_pass("cylinder", make_sample("cylinder"), Scheme::catmull_clark);  // whole edges beside halves
  expect_corner_pass("prism", test::prism_mesh(), Scheme::catmull_clark);
  expect_corner_pass("open cylinder", test::open_cylinder_mesh(), Scheme::catmull_clark);
  expect_corner_pass("icosphere", make_sample("icosphere"), Scheme::loop);
  expect_corner_pass("triangle grid", test::triangle_grid_mesh(4, 3), Scheme::loop);
  CovarianceMesh creased = make_sample("cube");
  creased.sharpness.set_crease(creased.edge(0)[0], creased.edge(0)[1], kInfiniteSharpness);
  creased.sharpness.set_crease(creased.edge(1)[0], creased.edge(1)[1], kInfiniteSharpness);
  expect_corner_pass("creased cube", creased, Scheme::catmull_clark);
}

}  // namespace
}  // namespace gps
