#include "core/modelling/samples.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <tuple>

#include "core/support/error.h"
#include "core/mesh/mesh_connectivity.h"
#include "core/reference/reference_subdivision.h"

namespace gps {
namespace {

TEST(Samples, EveryNamedSampleIsAValidCovarianceMesh) {
  for (const auto& name : sample_names()) {
    const CovarianceMesh m = make_sample(name, 200);
    EXPECT_GT(m.n_faces(), 0u) << name;
    EXPECT_NO_THROW(validate_gaussians(m, name)) << name;
    EXPECT_FALSE(sample_description(name).empty());
  }
  EXPECT_THROW(make_sample("teapot"), Error);
}

TEST(Samples, CountsAreAsDescribed) {
  const auto cube = make_sample("cube");
  EXPECT_EQ(cube.n_vertices(), 8u);
  EXPECT_EQ(cube.n_faces(), 6u);
  const auto cone = make_sample("cone");
  EXPECT_EQ(cone.n_vertices(), 9u);
  EXPECT_EQ(cone.n_faces(), 8u);
  EXPECT_DOUBLE_EQ(cone.mean(0).y(), 1.5);
  // The wirecube is closed and of genus 5: V − E + F = 2 − 2g = −8.
  const auto wire = make_sample("wirecube");
  EXPECT_EQ(int(wire.n_vertices()) - int(wire.n_edges()) + int(wire.n_faces()), -8);
  for (size_t e = 0; e < wire.n_edges(); ++e) EXPECT_FALSE(wire.is_boundary_edge(e));
}

// The pawn: a closed lathe mesh of quads with triangle fans at its poles, covariances inferred
// (anisotropic); its twin joins each pair of pole triangles into a quad.
TEST(Samples, PawnIsAClosedMixedMeshAndItsTwinAllQuads) {
  for (const auto& [name, quads, triangles] : {std::tuple{"pawn", 736, 64}, std::tuple{"pawn-quads", 768, 0}}) {
    const auto m = make_sample(name);
    int n_quads = 0, n_triangles = 0;
    for (size_t f = 0; f < m.n_faces(); ++f) (m.face_size(f) == 4 ? n_quads : n_triangles) += 1;
    EXPECT_EQ(n_quads, quads) << name;
    EXPECT_EQ(n_triangles, triangles) << name;
    EXPECT_EQ(int(m.n_vertices()) - int(m.n_edges()) + int(m.n_faces()), 2) << name;
    for (size_t e = 0; e < m.n_edges(); ++e) EXPECT_FALSE(m.is_boundary_edge(e)) << name;
    const Eigen::SelfAdjointEigenSolver<Mat3> eigen(m.covariance(100));
    EXPECT_GT(eigen.eigenvalues()[2], 2.0 * eigen.eigenvalues()[0]) << name << ": inferred, not isotropic";
  }
  EXPECT_EQ(make_sample("pawn").n_vertices(), make_sample("pawn-quads").n_vertices());
}

TEST(Samples, ValenceSamplesHaveOneExtraordinaryVertex) {
  for (int n = 3; n <= 10; ++n) {
    const auto m = make_sample("valence" + std::to_string(n));
    const MeshConnectivity& c = m.connectivity();
    int extraordinary = 0;
    for (int v = 0; v < int(m.n_vertices()); ++v) {
      const VertexRole role = vertex_role(c, v);
      if (role == VertexRole::interior && c.valence(v) != 4) {
        ++extraordinary;
        EXPECT_EQ(c.valence(v), n);
      }
      if (role == VertexRole::boundary) {
        EXPECT_EQ(c.valence(v), 3);
      }
    }
    EXPECT_EQ(extraordinary, n == 4 ? 0 : 1);
  }
}

TEST(Samples, SizedSamplesScale) {
  for (const int size : {1000, 10000, 100000}) {
    for (const char* name : {"grid", "sphere"}) {
      const double faces = double(make_sample(name, size).n_faces());
      EXPECT_NEAR(faces / size, 1.0, 0.1) << name << " " << size;
    }
  }
}

// The limit surface's profile: the highest point among limit vertices at distance [r0, r1) from the axis.
double height_at(const std::string& name, double r0, double r1) {
  const auto r = subdivide(make_sample(name), {Scheme::loop, 5, true, LoopBeta::warren});
  double y = -10;
  for (size_t i = 0; i < r.mesh.n_vertices(); ++i) {
    const Vec3 p = r.mesh.mean(i);
    const double radius = std::hypot(p.x(), p.z());
    if (radius >= r0 && radius < r1) y = std::max(y, p.y());
  }
  return y;
}

TEST(Samples, ConeVariantsBehaveAsThePaperShows) {
  const double iso = height_at("cone", 0, 1e-9);
  EXPECT_NEAR(iso, 0.0, 1e-9);  // Warren's Loop limit of the apex: the plain cone is far below 1.5
  EXPECT_GT(height_at("cone-pointy", 0, 1e-9), 1.49);   // a sharp tip at the apex
  EXPECT_LT(height_at("cone-pointy", 0.6, 1.6), -1.0);  // ... on a low, wide base
  const double concave_tip = height_at("cone-concave", 0, 1e-9);
  EXPECT_GT(concave_tip, iso + 1.0);
  EXPECT_LT(height_at("cone-concave", 0.2, 0.4), 0.5 * (concave_tip - 1.5));  // flanks below the straight line
  EXPECT_GT(height_at("cone-plateau", 0.0, 0.8), 1.49);                       // flat on top
  EXPECT_GT(height_at("cone-plateau", 0.6, 0.8), 1.4);
  EXPECT_LT(height_at("cone-plateau", 1.6, 1.8), 1.4);    // ... rounding off before the rim
  EXPECT_GT(height_at("cone-cylinder", 1.6, 1.8), 1.45);  // flat out to the rim: vertical sides
}

}  // namespace
}  // namespace gps
