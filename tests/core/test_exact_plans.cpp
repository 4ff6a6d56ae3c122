// Catmull-Clark plans evaluate extraordinary vertices exactly (issue 11): at every parameter the
// reference (GPS subdivision with limit projection) gives, not only at node corners.
#include <gtest/gtest.h>

#include <cstdio>

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

}  // namespace
}  // namespace gps
