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
#include "core/modelling/edge_operations.h"
#include "core/modelling/samples.h"
#include "core/plans/patch_adjacency.h"
#include "render/gl/gpu_layout.h"
#include "render/pipeline/corner_limit_pass.h"
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
// Returns how many corners it met whose patch's tangents run parallel there (evaluate_patch's fold).
int expect_corner_pass(const std::string& name, const CovarianceMesh& mesh, Scheme scheme) {
  PlanOptions options;
  options.scheme = scheme;
  const NormalisedFrame frame = NormalisedFrame::of(mesh);
  const test::PlannedMesh cpu(frame.to_frame(mesh), options);
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh, cpu.tables, frame);
  const PatchPlans& plans = cpu.tables.plans;
  const int n = plans.corners(), slots = n * plans.n_patches();
  const std::vector<float> pass = renderer.read_corner_pass();
  EXPECT_EQ(pass.size(), size_t(12 * slots)) << name;
  if (pass.size() != size_t(12 * slots)) return 0;
  int corners = 0, midpoints = 0, sharp = 0, folded = 0;
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
        EXPECT_TRUE(s.has_value()) << where;
        if (!s) continue;
        EXPECT_LT(distance(limit, s->position), 1e-4) << where << ": corner";
        folded += tangents_parallel(s->du, s->dv);
        EXPECT_LT(distance(limit + 4, s->normal), 1e-3) << where << ": normal";
      } else {
        EXPECT_TRUE(zero(limit, 8)) << where << ": a corner it does not evaluate";
      }
      if (curve_edge(plans, p, c) == PatchEdgeSlot{p, c}) {
        ++midpoints;
        const auto [u, v] = test::edge_point(plans.shape, c, 0.5);
        const auto s = evaluate_patch(plans, cpu.points, p, u, v);
        EXPECT_TRUE(s.has_value()) << where;
        if (s) EXPECT_LT(distance(midpoint, s->position), 1e-4) << where << ": midpoint";
        EXPECT_EQ(midpoint[3], 0.0f) << where;
      } else {
        EXPECT_TRUE(zero(midpoint, 4)) << where << ": a midpoint another edge holds";
      }
    }
  EXPECT_GT(corners, 0) << name;
  EXPECT_EQ(sharp > 0, !mesh.sharpness.empty()) << name << ": corners with normals of their own";
  EXPECT_GT(midpoints, slots / 4) << name;
  return folded;
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

// The evaluations on plans without an extraordinary node run in a program built without that branch
// (CornerLimitPass::all_items): the pawn's and the icosphere's patches are of both kinds, so the test
// above compared the results of both programs.
TEST_F(CornerPass, PlansWithAndWithoutAnExtraordinaryNodeAreEvaluatedApart) {
  for (const auto& [name, scheme] : {std::pair{"pawn", Scheme::catmull_clark}, std::pair{"icosphere", Scheme::loop}}) {
    PlanOptions options;
    options.scheme = scheme;
    const test::PlannedMesh planned(make_sample(name), options);
    const PatchPlans& plans = planned.tables.plans;
    const CornerItems items = CornerLimitPass::all_items(plans);
    EXPECT_GT(items.leaf_evaluations, 0) << name;
    EXPECT_LT(items.leaf_evaluations, items.evaluations) << name;
    for (int i = 0; i < items.evaluations; ++i) {
      const int patch = items.items[size_t(i)] / gpu::kCornerItemOps / plans.corners();
      EXPECT_EQ(holds_extraordinary_node(plans, plans.patch_roots[size_t(patch)]), i >= items.leaf_evaluations)
          << name << " item " << i;
    }
  }
}

// A boundary edge split in two: its new vertex is a corner of one face between two edges in one line,
// where that face's patch has parallel tangents and no normal of its own. The corner pass gives it the
// normal beside it (as the CPU does), not rounding's direction or 0/0, which every tessellated vertex
// there would take (non-finite pixels, which `gpsurf render` refuses to write).
TEST_F(CornerPass, ACornerBetweenTwoEdgesInALineTakesTheNormalBesideIt) {
  for (const auto& [n, m] : {std::pair{3, 2}, std::pair{8, 6}}) {
    const CovarianceMesh grid = test::grid_mesh(n, m);
    const MeshConnectivity& c = grid.connectivity();
    for (int e = 0; e < c.n_edges(); e += 5) {
      if (!c.is_boundary_edge(e)) continue;
      const std::string name =
          std::to_string(n) + "×" + std::to_string(m) + " grid with boundary edge " + std::to_string(e) + " split";
      const CovarianceMesh split = split_edge(grid, c.edge_verts[2 * size_t(e)], c.edge_verts[2 * size_t(e) + 1]).mesh;
      EXPECT_GE(expect_corner_pass(name, split, Scheme::catmull_clark), 1) << name;
    }
  }
}

}  // namespace
}  // namespace gps
