// The reference's exact limit normals (core/reference/limit_tangents.h): they are those of the
// refined surface (its faces' normals closing in on them level by level), and the plans' evaluator
// gives the same normal at every reference vertex, extraordinary vertices and boundaries included.
#include "core/reference/limit_tangents.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>
#include <string>

#include "core/reference/reference_subdivision.h"
#include "tests/support/plan_fixture.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

using test::with_random_covariances;

struct Case {
  std::string name;
  CovarianceMesh mesh;
  Scheme scheme;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  for (int n = 3; n <= 16; ++n) {
    const CovarianceMesh bipyramid = with_random_covariances(test::bipyramid_mesh(n), unsigned(n));
    out.push_back({"bipyramid " + std::to_string(n) + " (Catmull-Clark)", bipyramid, Scheme::catmull_clark});
    out.push_back({"bipyramid " + std::to_string(n) + " (Loop)", bipyramid, Scheme::loop});
  }
  for (const char* name : {"valence3", "valence5", "valence8", "valence10", "cube", "wirecube", "cylinder", "pawn"})
    out.push_back({name, make_sample(name), Scheme::catmull_clark});
  for (const char* name : {"cone", "cone-pointy", "cone-concave", "cone-plateau", "cone-cylinder"}) {
    out.push_back({std::string(name) + " (Loop)", make_sample(name), Scheme::loop});
    out.push_back({std::string(name) + " (Catmull-Clark)", make_sample(name), Scheme::catmull_clark});
  }
  out.push_back({"open cylinder", with_random_covariances(test::open_cylinder_mesh(), 6), Scheme::catmull_clark});
  out.push_back({"triangle grid (Loop)", with_random_covariances(test::triangle_grid_mesh(4, 3), 5), Scheme::loop});
  out.push_back({"triangle grid (Catmull-Clark)", with_random_covariances(test::triangle_grid_mesh(4, 3), 5),
                 Scheme::catmull_clark});
  return out;
}

double degrees_between(const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / M_PI; }

// At every vertex of three levels of the reference, the evaluator's normal at the vertex's
// parameter (core/evaluation/patch_eval.h: exact plans, Stam's eigenbases at extraordinary vertices) and the
// reference's from its tangent masks are one normal. Boundary vertices whose ring has no two
// separated subdominant eigenvalues have none; they are counted, and must be few.
TEST(LimitNormals, EqualTheEvaluatorsAtEveryReferenceVertex) {
  for (const Case& c : cases()) {
    const auto ref = subdivide(c.mesh, {c.scheme, 3, true, LoopBeta::loop, true});
    const test::PlannedMesh p(c.mesh, PlanOptions{c.scheme});
    double worst = 0;
    int missing = 0;
    for (size_t k = 0; k < ref.mesh.n_vertices(); ++k) {
      if (ref.normals[k].isZero(0.0)) {
        ++missing;
        continue;
      }
      const PatchParam& pp = ref.vertex_params[k];
      const auto s = evaluate_patch(p.tables.plans, p.points, pp.patch, pp.u, pp.v);
      ASSERT_TRUE(s) << c.name << " vertex " << k;
      worst = std::max(worst, degrees_between(s->normal, ref.normals[k]));
    }
    std::printf("%-32s %6zu vertices, largest angle %.1e degrees, %d without masks\n", c.name.c_str(),
                ref.mesh.n_vertices(), worst, missing);
    EXPECT_LT(worst, 1e-8) << c.name;
    EXPECT_LE(missing, 16) << c.name;
  }
}

// The masks' normals are the refined surface's: at every regular vertex (interior valence 4 or 6,
// boundary valence 3 or 4) the normal of its fan of faces further down closes in on the mask's:
// central differences of the reference inside (error O(h²): ÷16 for two levels), one-sided on a
// boundary (O(h): ÷4). Extraordinary vertices, whose fans converge only as fast as their
// subdominant eigenvalues let them, are ExactPlans.NormalsAreDefinedAtExtraordinaryVertices'. The
// needle and the disc of cone-concave and cone-plateau are narrower than a fan six levels down,
// where these differences have not begun to converge; they are in the test above. So is the pawn, of
// three million faces six levels down: its vertices are regular or extraordinary as the others' are.
TEST(LimitNormals, AreTheNormalsOfTheRefinedSurface) {
  for (const Case& c : cases()) {
    if (c.name.find("concave") != std::string::npos || c.name.find("plateau") != std::string::npos || c.name == "pawn")
      continue;
    const auto coarse = subdivide(c.mesh, {c.scheme, 2, true, LoopBeta::loop, true});
    const PolygonTopology& coarse_topology = coarse.mesh.topology();
    const MeshConnectivity& connectivity = coarse.mesh.connectivity();
    const int regular = c.scheme == Scheme::loop ? 6 : 4;
    double worst[2][2] = {{0, 0}, {0, 0}};  // [interior, boundary][2, 4 levels down]
    for (int extra = 0; extra < 2; ++extra) {
      const auto fine = subdivide(c.mesh, {c.scheme, 4 + 2 * extra, true});
      const PolygonTopology& t = fine.mesh.topology();
      std::vector<Vec3> fan(fine.mesh.n_vertices(), Vec3::Zero());
      for (int f = 0; f < t.n_faces(); ++f) {
        const int o = t.offsets[size_t(f)], n = t.face_size(f);
        const auto at = [&](int i) { return fine.mesh.mean(size_t(t.verts[size_t(o + i % n)])); };
        for (int i = 0; i < n; ++i)
          fan[size_t(t.verts[size_t(o + i)])] += (at(i + 1) - at(i)).cross(at(i + n - 1) - at(i));
      }
      for (int k = 0; k < coarse_topology.n_vertices; ++k) {  // vertex points keep their indices
        const VertexRole role = vertex_role(connectivity, k);
        const int valence = connectivity.valence(k);
        const bool interior = role == VertexRole::interior && valence == regular;
        const bool boundary = role == VertexRole::boundary && valence == regular / 2 + 1;
        if (!interior && !boundary) continue;
        double& w = worst[boundary][extra];
        w = std::max(w, degrees_between(coarse.normals[size_t(k)], fan[size_t(k)]));
      }
    }
    std::printf(
        "%-32s largest angle to the fan, 2 and 4 levels down: inside %.2e, %.2e; on the boundary %.2e, %.2e degrees\n",
        c.name.c_str(), worst[0][0], worst[0][1], worst[1][0], worst[1][1]);
    EXPECT_LT(worst[0][1], 0.5) << c.name;
    EXPECT_LE(worst[0][1], worst[0][0] / 10.0)
        << c.name << ": inside, the fan does not close in on the mask normal as h²";
    EXPECT_LT(worst[1][1], 1.0) << c.name;
    if (worst[1][1] > 0.01) {  // below that, cone-pointy's Loop boundary has not settled into its rate
      EXPECT_LE(worst[1][1], worst[1][0] / 3.0)
          << c.name << ": on the boundary, the fan does not close in on the mask normal as h";
    }
  }
}

}  // namespace
}  // namespace gps
