// Catmull-Clark plans evaluate extraordinary vertices exactly (issue 11): at every parameter the
// reference (GPS subdivision with limit projection) gives, not only at node corners.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>
#include <random>

#include "core/mesh_connectivity.h"
#include "core/patch_eval.h"
#include "core/reference_subdivision.h"
#include "tests/support/plan_fixture.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

using test::PlannedMesh;
using test::with_random_covariances;

PlannedMesh exact_plans(CovarianceMesh m) { return PlannedMesh(std::move(m), PlanOptions{Scheme::catmull_clark}); }

// A closed quad mesh with two extraordinary vertices of valence n and 2n of valence 3: the
// bipyramid of triangles after one Catmull-Clark step.
CovarianceMesh quad_bipyramid(int n) { return subdivide(test::bipyramid_mesh(n), {Scheme::catmull_clark, 1, false}).mesh; }

// Largest distance, relative to the bounding-box diagonal, between the plans at a reference
// vertex's parameter and that vertex.
double error_against_reference(const PlannedMesh& p, int levels) {
  const auto ref = subdivide(p.mesh, {Scheme::catmull_clark, levels, true});
  const double diag = bounding_box_diagonal(p.mesh);
  double worst = 0;
  for (size_t k = 0; k < ref.mesh.n_vertices(); ++k) {
    const PatchParam& pp = ref.vertex_params[k];
    const auto s = evaluate_patch(p.tables.plans, p.points, pp.patch, pp.u, pp.v);
    EXPECT_TRUE(s.has_value());
    if (s) worst = std::max(worst, (s->position - ref.mesh.mean(k)).norm() / diag);
  }
  return worst;
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
  for (int n = 3; n <= 10; ++n) cases.emplace_back("valence" + std::to_string(n), make_sample("valence" + std::to_string(n)));
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
      const auto at = [&](double ds, double dt) { return evaluate_patch(p.tables.plans, p.points, patch, s + ds, t + dt)->position; };
      const Vec3 du = (at(h, 0) - at(-h, 0)) / (2 * h), dv = (at(0, h) - at(0, -h)) / (2 * h);
      EXPECT_LT((c->du - du).norm(), 1e-5 * du.norm()) << name << " patch " << patch << " at " << s << ", " << t;
      EXPECT_LT((c->dv - dv).norm(), 1e-5 * dv.norm()) << name << " patch " << patch << " at " << s << ", " << t;
    }
    EXPECT_GT(extraordinary, 40) << name;
  }
}

// At the extraordinary vertex itself the normal is defined (from the limit tangent masks) and is
// the reference surface's: the normal of the fan of limit points around the vertex at level 7 (its fan is within 0.5°; at level 6, 0.9° at valence 12).
TEST(ExactPlans, NormalsAreDefinedAtExtraordinaryVertices) {
  for (int n : {3, 6, 12}) {
    const CovarianceMesh mesh = with_random_covariances(quad_bipyramid(n), unsigned(n));
    const PlannedMesh p = exact_plans(mesh);
    const auto ref = subdivide(mesh, {Scheme::catmull_clark, 7, true});
    const auto fine = connectivity_of(topology_of(ref.mesh.mesh));
    int checked = 0;
    for (size_t k = 0; k < ref.mesh.n_vertices(); ++k) {
      const PatchParam& pp = ref.vertex_params[k];
      if (pp.u != 0 || pp.v != 0) continue;
      const auto s = evaluate_patch(p.tables.plans, p.points, pp.patch, 0.0, 0.0);
      ASSERT_TRUE(s);
      if (s->kind != NodeKind::extraordinary || fine.valence(int(k)) == 4) continue;
      // The reference's normal: Σ (x_i − x) × (x_{i+1} − x) over the ring, in face order.
      Vec3 normal = Vec3::Zero();
      const auto& t = topology_of(ref.mesh.mesh);
      for (int i = fine.vertex_face_offsets[k]; i < fine.vertex_face_offsets[k + 1]; ++i) {
        const int f = fine.vertex_faces[size_t(i)], c = fine.vertex_face_corners[size_t(i)];
        const auto vertex = [&](int j) { return ref.mesh.mean(size_t(t.verts[size_t(t.offsets[size_t(f)] + (c + j) % 4)])); };
        normal += (vertex(1) - vertex(0)).cross(vertex(3) - vertex(0));
      }
      const double angle = std::acos(std::clamp(s->normal.dot(normal.normalized()), -1.0, 1.0)) * 180.0 / M_PI;
      EXPECT_LT(angle, 0.5) << "valence " << n << " vertex " << k;
      ++checked;
    }
    EXPECT_GT(checked, 0) << "valence " << n;
  }
}

}  // namespace
}  // namespace gps
