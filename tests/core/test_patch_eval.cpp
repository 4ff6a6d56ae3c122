// The patch bases and the Bézier rules of the terminal nodes.
#include "core/evaluation/patch_eval.h"

#include <gtest/gtest.h>

#include <random>

#include "core/patches/patch_basis.h"
#include "tests/support/plan_fixture.h"

namespace gps {
namespace {

TEST(PatchBasis, PartitionOfUnityAndDerivatives) {
  for (int k = 0; k <= 20; ++k) {
    const double t = k / 20.0, h = 1e-6;
    for (auto basis : {&bspline_basis, &bezier_basis}) {
      double w[4], dw[4], wp[4], wm[4], unused[4];
      basis(t, w, dw);
      basis(t + h, wp, unused);
      basis(t - h, wm, unused);
      double sum = 0, dsum = 0;
      for (int i = 0; i < 4; ++i) {
        EXPECT_GE(w[i], -1e-15);
        EXPECT_NEAR(dw[i], (wp[i] - wm[i]) / (2 * h), 1e-8);
        sum += w[i];
        dsum += dw[i];
      }
      EXPECT_NEAR(sum, 1.0, 1e-15);
      EXPECT_NEAR(dsum, 0.0, 1e-14);
    }
  }
  // Segment joins: the B-spline at t = 1 equals the next segment at t = 0, shifted by one point.
  double a[4], da[4], b[4], db[4];
  bspline_basis(1.0, a, da);
  bspline_basis(0.0, b, db);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(a[i + 1], b[i], 1e-15);
    EXPECT_NEAR(da[i + 1], db[i], 1e-15);
  }
}

// With n = 4 the terminal rules (thesis Fig. 2.5) are the B-spline → Bézier conversion: building every
// regular node as a Bézier node changes no position and no derivative (interior, boundary, corners).
TEST(PatchEval, RegularNodesAsBezierEqualTheBspline) {
  for (const char* name : {"grid", "valence5", "cylinder", "wirecube"}) {
    CovarianceMesh mesh = make_sample(name, 64);
    const test::PlannedMesh p(mesh, 2);
    const SurfaceTables bezier = build_plans(p.mesh.topology(), 2, ExtraordinaryNodes::bezier, false);
    const auto points = apply_stencils(bezier.stencils, p.base);
    ASSERT_EQ(bezier.plans.n_patches(), p.tables.plans.n_patches());
    int terminal_instead_of_regular = 0;
    for (int patch = 0; patch < p.tables.plans.n_patches(); ++patch)
      for (int i = 0; i <= 6; ++i)
        for (int j = 0; j <= 6; ++j) {
          Dual q0, u0, v0, q1, u1, v1;
          NodeKind k0, k1;
          int d0, d1;
          evaluate_dual(p.tables.plans, p.points, patch, i / 6.0, j / 6.0, q0, u0, v0, &d0, &k0);
          evaluate_dual(bezier.plans, points, patch, i / 6.0, j / 6.0, q1, u1, v1, &d1, &k1);
          EXPECT_EQ(k1, NodeKind::terminal);
          terminal_instead_of_regular += k0 == NodeKind::regular;
          const double scale = 1 + q0.norm() + u0.norm() + v0.norm();
          EXPECT_LT((q0 - q1).norm(), 1e-12 * scale) << name << " patch " << patch;
          EXPECT_LT((u0 - u1).norm(), 1e-11 * scale) << name << " patch " << patch;
          EXPECT_LT((v0 - v1).norm(), 1e-11 * scale) << name << " patch " << patch;
        }
    EXPECT_GT(terminal_instead_of_regular, 100) << name;
  }
}

// Patch parameters on node borders (u = ½, u = 1) descend consistently: the surface is continuous there.
TEST(PatchEval, ContinuousAcrossNodeBorders) {
  const test::PlannedMesh p(make_sample("valence7"), 4);
  const double diag = bounding_box_diagonal(p.mesh);
  for (int patch = 0; patch < p.tables.plans.n_patches(); ++patch)
    for (const double border : {0.5, 0.25, 0.125, 0.0625, 1.0}) {
      for (int k = 0; k <= 8; ++k) {
        const double t = k / 8.0, h = 1e-9;
        const auto a = evaluate_patch(p.tables.plans, p.points, patch, border, t);
        const auto b = evaluate_patch(p.tables.plans, p.points, patch, border - h, t);
        const auto c = evaluate_patch(p.tables.plans, p.points, patch, t, border);
        const auto d = evaluate_patch(p.tables.plans, p.points, patch, t, border - h);
        ASSERT_TRUE(a && b && c && d);
        EXPECT_LT((a->position - b->position).norm(), 1e-7 * diag);
        EXPECT_LT((c->position - d->position).norm(), 1e-7 * diag);
      }
    }
}

}  // namespace
}  // namespace gps
