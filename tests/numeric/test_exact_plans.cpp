// Catmull-Clark plans evaluate extraordinary vertices exactly: at every parameter the
// reference (GPS subdivision with limit projection) gives, not only at node corners.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "core/mesh/mesh_connectivity.h"
#include "core/patches/patch_basis.h"
#include "core/evaluation/patch_eval.h"
#include "core/reference/reference_subdivision.h"
#include "tests/support/plan_fixture.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

using test::PlannedMesh;
using test::with_random_covariances;

PlannedMesh exact_plans(CovarianceMesh m) { return PlannedMesh(std::move(m), PlanOptions{Scheme::catmull_clark}); }

// A closed quad mesh with two extraordinary vertices of valence n and 2n of valence 3: the
// bipyramid of triangles after one Catmull-Clark step.
CovarianceMesh quad_bipyramid(int n) {
  return subdivide(test::bipyramid_mesh(n), {Scheme::catmull_clark, 1, false}).mesh;
}

double error_against_reference(const PlannedMesh& p, int levels) {
  return test::error_against_reference(p, {Scheme::catmull_clark, levels, true});
}

TEST(ExactPlans, EqualTheReferenceAtInteriorExtraordinaryVertices) {
  for (int n = 3; n <= 16; ++n) {
    const PlannedMesh p = exact_plans(with_random_covariances(quad_bipyramid(n), unsigned(n)));
    const double error = error_against_reference(p, n <= 8 ? 6 : 5);
    std::printf("quad bipyramid %2d: %.1e of the diagonal\n", n, error);
    EXPECT_LT(error, 1e-9) << "valence " << n;
  }
  for (const char* name : {"cube", "wirecube", "torus"}) {
    const double error = error_against_reference(exact_plans(with_random_covariances(make_sample(name), 3)), 5);
    std::printf("%-17s: %.1e of the diagonal\n", name, error);
    EXPECT_LT(error, 1e-9) << name;
  }
}

TEST(ExactPlans, EqualTheReferenceAtBoundaryVerticesAndSplitFaces) {
  std::vector<std::pair<std::string, CovarianceMesh>> cases;
  for (int n = 3; n <= 10; ++n)
    cases.emplace_back("valence" + std::to_string(n), make_sample("valence" + std::to_string(n)));
  for (const char* name : {"cone", "cone-pointy", "cylinder", "pawn"}) cases.emplace_back(name, make_sample(name));
  cases.emplace_back("triangle grid", with_random_covariances(test::triangle_grid_mesh(4, 3), 5));
  cases.emplace_back("open cylinder", with_random_covariances(test::open_cylinder_mesh(), 6));
  cases.emplace_back("prism", with_random_covariances(test::prism_mesh(), 7));
  for (const auto& [name, mesh] : cases) {
    const double error = error_against_reference(exact_plans(mesh), 5);
    std::printf("%-17s: %.1e of the diagonal\n", name.c_str(), error);
    EXPECT_LT(error, 1e-9) << name;
  }
}

// Analytic derivatives (thesis Eq. 3.12 from q_u, q_v) against central differences, at random
// parameters and at parameters closing in on the extraordinary corner (n levels down the tables).
TEST(ExactPlans, DerivativesMatchFiniteDifferences) {
  for (const char* name : {"valence5", "valence9", "cube"}) {
    const PlannedMesh p = exact_plans(with_random_covariances(make_sample(name), 4));
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int extraordinary = 0;
    for (int k = 0; k < 400; ++k) {
      const int patch = int(u(rng) * p.tables.plans.n_patches());
      const double scale = k % 2 ? 1.0 : std::ldexp(1.0, -int(u(rng) * 12));  // half near a corner
      const double s = 0.02 + 0.96 * scale * u(rng), t = 0.02 + 0.96 * scale * u(rng), h = 1e-5 * scale;
      const auto c = evaluate_patch(p.tables.plans, p.points, patch, s, t);
      ASSERT_TRUE(c);
      extraordinary += c->kind == NodeKind::extraordinary;
      const auto at = [&](double ds, double dt) {
        return evaluate_patch(p.tables.plans, p.points, patch, s + ds, t + dt)->position;
      };
      const Vec3 du = (at(h, 0) - at(-h, 0)) / (2 * h), dv = (at(0, h) - at(0, -h)) / (2 * h);
      EXPECT_LT((c->du - du).norm(), 1e-5 * du.norm()) << name << " patch " << patch << " at " << s << ", " << t;
      EXPECT_LT((c->dv - dv).norm(), 1e-5 * dv.norm()) << name << " patch " << patch << " at " << s << ", " << t;
    }
    EXPECT_GT(extraordinary, 15) << name;
  }
}

// Past the tables' kExtraordinaryLevels levels the evaluator steps the node's points by the table's A
// (core/plans/plan_descent.h): the surface goes on smoothly across each level where that starts (a wrong
// A or row would break it there by far more than the window's width) and closes in on the limit
// point, normals defined, down to 2^-60 of the patch. Both schemes, interior and boundary vertices.
TEST(ExactPlans, PastTheTablesLevelsStepsContinueTheSurface) {
  const std::vector<std::pair<std::string, PlannedMesh>> cases = [] {
    std::vector<std::pair<std::string, PlannedMesh>> c;
    c.emplace_back("valence5, Catmull-Clark", exact_plans(with_random_covariances(make_sample("valence5"), 5)));
    c.emplace_back("quad bipyramid 7", exact_plans(with_random_covariances(quad_bipyramid(7), 7)));
    c.emplace_back("bipyramid 7, Loop",
                   PlannedMesh(with_random_covariances(test::bipyramid_mesh(7), 8), PlanOptions{Scheme::loop}));
    c.emplace_back("triangle grid, Loop",
                   PlannedMesh(with_random_covariances(test::triangle_grid_mesh(4, 3), 9), PlanOptions{Scheme::loop}));
    return c;
  }();
  for (const auto& [name, p] : cases) {
    const bool quad = p.tables.plans.shape == PatchShape::quad;
    const double diag = bounding_box_diagonal(p.mesh);
    int corners = 0;
    for (int patch = 0; patch < p.tables.plans.n_patches(); ++patch)
      for (int r = 0; r < (quad ? 4 : 3); ++r) {
        // The point h along a direction into the patch from corner r; `measure` is what locate halves
        // (max(s, t) for quads, s + t for triangles), so h = 2^-k / measure is where level k starts.
        const double a = 0.37, b = 0.61, measure = quad ? b : a + b;
        const auto uv = [&](double h) -> std::pair<double, double> {
          if (!quad)
            return r == 0   ? std::pair{h * a, h * b}
                   : r == 1 ? std::pair{1 - h * (a + b), h * a}
                            : std::pair{h * b, 1 - h * (a + b)};
          const double cu[4] = {0, 1, 1, 0}, cv[4] = {0, 0, 1, 1}, su[4] = {1, -1, -1, 1}, sv[4] = {1, 1, -1, -1};
          return {cu[r] + su[r] * h * a, cv[r] + sv[r] * h * b};
        };
        const auto at = [&, &p = p](double h) {
          const auto [u, v] = uv(h);
          return evaluate_patch(p.tables.plans, p.points, patch, u, v);
        };
        const auto near = at(std::ldexp(1.0, -20));
        if (!near || near->kind != NodeKind::extraordinary) continue;
        ++corners;
        const auto corner = at(0.0);
        ASSERT_TRUE(corner);
        for (int k = kExtraordinaryLevels - 2; k <= kExtraordinaryLevels + 2; ++k) {
          const double h = std::ldexp(1.0, -k) / measure, delta = 1e-7;
          const auto below = at(h * (1 - delta)), above = at(h * (1 + delta)), mid = at(h);
          ASSERT_TRUE(below && above && mid);
          const auto [du, dv] = std::pair{uv(h * (1 + delta)).first - uv(h * (1 - delta)).first,
                                          uv(h * (1 + delta)).second - uv(h * (1 - delta)).second};
          const Vec3 expected = du * mid->du + dv * mid->dv;
          EXPECT_LT((above->position - below->position - expected).norm(), 1e-3 * expected.norm() + 1e-14 * diag)
              << name << " patch " << patch << " corner " << r << " at level " << k;
        }
        double last = std::numeric_limits<double>::infinity();
        for (int m = 1; m <= 60; ++m) {
          const auto s = at(std::ldexp(1.0, -m));
          ASSERT_TRUE(s);
          const double distance = (s->position - corner->position).norm();
          EXPECT_LE(distance, last * (1 + 1e-9) + 1e-15 * diag)
              << name << " patch " << patch << " corner " << r << " at 2^-" << m;
          EXPECT_TRUE(s->normal.allFinite()) << name << " patch " << patch << " corner " << r << " at 2^-" << m;
          last = distance;
        }
        EXPECT_LT(last, 1e-12 * diag) << name << " patch " << patch << " corner " << r;
      }
    std::printf("%-24s: %d extraordinary corners\n", name.c_str(), corners);
    EXPECT_GT(corners, 2) << name;
  }
}

// At the extraordinary vertex itself the normal is defined (from the limit tangent masks) and is
// the reference surface's: the normal of the fan of limit points around the vertex at level 7 (its fan is within 0.5°;
// at level 6, 0.9° at valence 12).
TEST(ExactPlans, NormalsAreDefinedAtExtraordinaryVertices) {
  for (int n : {3, 6, 12}) {
    const CovarianceMesh mesh = with_random_covariances(quad_bipyramid(n), unsigned(n));
    const PlannedMesh p = exact_plans(mesh);
    const auto ref = subdivide(mesh, {Scheme::catmull_clark, 7, true});
    const auto& fine = ref.mesh.connectivity();
    int checked = 0;
    for (size_t k = 0; k < ref.mesh.n_vertices(); ++k) {
      const PatchParam& pp = ref.vertex_params[k];
      if (pp.u != 0 || pp.v != 0) continue;
      const auto s = evaluate_patch(p.tables.plans, p.points, pp.patch, 0.0, 0.0);
      ASSERT_TRUE(s);
      if (s->kind != NodeKind::extraordinary || fine.valence(int(k)) == 4) continue;
      // The reference's normal: Σ (x_i − x) × (x_{i+1} − x) over the ring, in face order.
      Vec3 normal = Vec3::Zero();
      const auto& t = ref.mesh.topology();
      for (int i = fine.vertex_face_offsets[k]; i < fine.vertex_face_offsets[k + 1]; ++i) {
        const int f = fine.vertex_faces[size_t(i)], c = fine.vertex_face_corners[size_t(i)];
        const auto vertex = [&](int j) {
          return ref.mesh.mean(size_t(t.verts[size_t(t.offsets[size_t(f)] + (c + j) % 4)]));
        };
        normal += (vertex(1) - vertex(0)).cross(vertex(3) - vertex(0));
      }
      const double angle = std::acos(std::clamp(s->normal.dot(normal.normalized()), -1.0, 1.0)) * 180.0 / M_PI;
      EXPECT_LT(angle, 0.5) << "valence " << n << " vertex " << k;
      ++checked;
    }
    EXPECT_GT(checked, 0) << "valence " << n;
  }
}

// With exact nodes the plans stop one level below an irregular vertex (two below a split face's
// centre), whatever depth is asked for, and need far fewer stencil rows than the thesis' plans.
TEST(ExactPlans, StopOneLevelBelowIrregularVertices) {
  for (const char* name : {"cube", "valence7", "wirecube", "cylinder", "cone-pointy", "pawn", "sphere"}) {
    const PolygonTopology t = make_sample(name).topology();
    const SurfaceTables exact = build_surface_plans(t, PlanOptions{Scheme::catmull_clark});
    const SurfaceTables thesis = build_surface_plans(t, PlanOptions{Scheme::catmull_clark, 3, LoopBeta::loop, false});
    std::printf("%-12s exact: depth %d, %d rows, %zu nodes; thesis depth 3: %d rows, %zu nodes\n", name,
                exact.plans.max_depth, exact.stencils.n_rows(), exact.plans.nodes.size(), thesis.stencils.n_rows(),
                thesis.plans.nodes.size());
    EXPECT_LE(exact.plans.max_depth, 2) << name;
    EXPECT_LT(exact.stencils.n_rows(), thesis.stencils.n_rows()) << name;
    const std::vector<Dual> points(size_t(exact.stencils.n_points()),
                                   Dual::Zero());  // the node kinds are what is looked at
    int terminal = 0;
    for (int patch = 0; patch < exact.plans.n_patches(); ++patch)
      for (const double u : {0.1, 0.4, 0.6, 0.9})
        for (const double v : {0.1, 0.4, 0.6, 0.9}) {
          NodeKind kind;
          Dual q, q_u, q_v;
          evaluate_dual(exact.plans, points, patch, u, v, q, q_u, q_v, nullptr, &kind);
          terminal += kind == NodeKind::terminal;
        }
    EXPECT_EQ(terminal, 0) << name << ": no approximate (Bézier) node is left";
  }
}

}  // namespace
}  // namespace gps
