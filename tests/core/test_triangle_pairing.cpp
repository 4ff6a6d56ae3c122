// Pairing triangles into quads (core/fitting/triangle_pairing.h): the squarest, flattest pairs
// joined, each triangle once, across no crease and no fold, the orientation and Gaussians kept.
#include <gtest/gtest.h>

#include <vector>

#include "core/fitting/triangle_pairing.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

// A flat n × n grid of unit squares in z = 0, each cut by its diagonal into two counter-clockwise
// triangles.
CovarianceMesh cut_squares(int n) {
  std::vector<Vec3> p;
  std::vector<std::vector<int>> faces;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) p.emplace_back(i, j, 0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      faces.push_back({a, a + 1, a + n + 2});
      faces.push_back({a, a + n + 2, a + n + 1});
    }
  return make_covariance_mesh(p, std::vector<Mat3>(p.size(), 0.01 * Mat3::Identity()), faces, "grid");
}

Vec3 face_normal(const CovarianceMesh& m, size_t f) {
  Vec3 n = Vec3::Zero();
  std::vector<Vec3> c;
  for (const int v : m.face(f)) c.push_back(m.mean(size_t(v)));
  for (size_t k = 0; k < c.size(); ++k) n += c[k].cross(c[(k + 1) % c.size()]);
  return n;
}

TEST(TrianglePairing, CutSquaresBecomeTheSquaresAgain) {
  CovarianceMesh m = cut_squares(4);
  const CovarianceMesh before = m;
  EXPECT_EQ(pair_triangles(m), 16u);
  ASSERT_EQ(m.n_faces(), 16u);
  EXPECT_EQ(m.n_vertices(), before.n_vertices());
  for (size_t f = 0; f < m.n_faces(); ++f) {
    EXPECT_EQ(m.face_size(f), 4);
    EXPECT_GT(face_normal(m, f).z(), 0.99) << "face " << f << " turned over";
  }
  for (size_t v = 0; v < m.n_vertices(); ++v) {
    EXPECT_EQ(m.mean(v), before.mean(v));
    EXPECT_EQ(m.covariances[v], before.covariances[v]);
  }
}

TEST(TrianglePairing, NoQuadAcrossACrease) {
  CovarianceMesh m = cut_squares(3);
  m.sharpness.set_crease(0, 5, 2.0);  // the first square's diagonal
  EXPECT_EQ(pair_triangles(m), 8u);
  EXPECT_EQ(m.n_faces(), 8u + 2u);
  EXPECT_EQ(m.sharpness.crease(0, 5), 2.0);
  EXPECT_GE(m.find_edge(0, 5), 0);
}

TEST(TrianglePairing, FoldedOrSkewPairsStayTriangles) {
  // The icosahedron's neighbours fold by 41.8°.
  CovarianceMesh icosahedron = test::icosahedron_mesh();
  EXPECT_EQ(pair_triangles(icosahedron), 0u);
  EXPECT_EQ(icosahedron.n_faces(), 20u);
  // Tighter limits than the grid's 45° rhombi: its triangles (60° corners) stay.
  CovarianceMesh grid = test::triangle_grid_mesh(4, 3);
  EXPECT_EQ(pair_triangles(grid, {20, 30}), 0u);
  EXPECT_GT(pair_triangles(grid), 0u);
}

}  // namespace
}  // namespace gps
