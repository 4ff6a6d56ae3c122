// Splitting and flipping one edge: counts, faces kept triangles, manifold and oriented, the new
// vertex's Gaussian, refusals that name the edge; on equal isotropic Gaussians a split edge's GPS
// limit is plain Catmull-Clark's.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <limits>
#include <map>

#include "core/modelling/samples.h"
#include "core/modelling/edge_operations.h"
#include "core/reference/reference_subdivision.h"
#include "tests/support/error_of.h"
#include "tests/support/test_meshes.h"
#include "tests/support/mesh_checks.h"

namespace gps {
namespace {

using test::expect_same_arrays;

using test::error_of;

// Checks that every directed edge lies in one face at most (manifold, consistently oriented);
// returns the number of boundary edges.
int checked_boundary_edges(const CovarianceMesh& m) {
  const MeshArrays a = arrays_of(m);
  std::map<std::pair<int, int>, int> directed;
  for (const auto& f : a.faces)
    for (size_t k = 0; k < f.size(); ++k) ++directed[{f[k], f[(k + 1) % f.size()]}];
  int boundary = 0;
  for (const auto& [e, n] : directed) {
    EXPECT_EQ(n, 1) << "directed edge " << e.first << "→" << e.second;
    if (!directed.count({e.second, e.first})) ++boundary;
  }
  return boundary;
}

bool all_triangles(const CovarianceMesh& m) {
  for (const auto& f : arrays_of(m).faces)
    if (f.size() != 3) return false;
  return true;
}

std::vector<Vec3> limit_means(const CovarianceMesh& m, int levels) {
  SubdivisionOptions o;
  o.levels = levels;
  o.limit = true;
  const SubdivisionResult r = subdivide(m, o);
  std::vector<Vec3> p;
  for (size_t v = 0; v < r.mesh.n_vertices(); ++v) p.push_back(r.mesh.mean(v));
  return p;
}

TEST(SplitEdge, SplitsBothTrianglesAndBlendsTheGaussians) {
  const CovarianceMesh m = test::with_random_covariances(test::icosahedron_mesh(), 9);
  const MeshArrays before = arrays_of(m);
  const Modelled r = split_edge(m, 5, 0, 0.3);  // faces 0 {0, 11, 5} and 1 {0, 5, 1}
  const MeshArrays a = arrays_of(r.mesh);
  ASSERT_EQ(a.n_vertices(), 13);
  ASSERT_EQ(a.n_faces(), 22);
  EXPECT_TRUE(all_triangles(r.mesh));
  EXPECT_EQ(checked_boundary_edges(r.mesh), 0);
  EXPECT_EQ(r.selection, (std::vector<int>{12}));
  EXPECT_EQ(r.summary, "split edge 5–0: 1 vertex, 2 faces added");
  // The pieces at 5 keep the faces' indices.
  EXPECT_EQ(a.faces[0], (std::vector<int>{5, 12, 11}));
  EXPECT_EQ(a.faces[1], (std::vector<int>{12, 5, 1}));
  EXPECT_EQ(a.faces[20], (std::vector<int>{12, 0, 11}));
  EXPECT_EQ(a.faces[21], (std::vector<int>{0, 12, 1}));
  const Gaussian want = blend_gaussians(before, {{5, 0.7}, {0, 0.3}});
  EXPECT_LE((a.means[12] - want.mean).norm(), 1e-14);
  EXPECT_LE((a.covariances[12] - want.covariance).norm(), 1e-14 * want.covariance.norm());
  expect_same_arrays(arrays_of(m), before);
}

TEST(SplitEdge, EqualIsotropicGaussiansGiveTheLinearPoint) {
  const CovarianceMesh m = test::triangle_grid_mesh(3, 2);
  for (double t : {0.5, 0.25, 0.9}) {
    const Modelled r = split_edge(m, 1, 2, t);  // on the boundary: one triangle beside it
    const MeshArrays a = arrays_of(r.mesh);
    EXPECT_EQ(a.n_faces(), int(m.n_faces()) + 1);
    EXPECT_EQ(checked_boundary_edges(r.mesh), checked_boundary_edges(m) + 1);
    const Vec3 want = (1 - t) * m.mean(1) + t * m.mean(2);
    EXPECT_LE((a.means.back() - want).norm(), 4e-16 * (1 + want.norm())) << "t = " << t;
    EXPECT_LE((a.covariances.back() - m.covariance(1)).norm(), 4e-16 * m.covariance(1).norm());
  }
}

TEST(SplitEdge, OtherFacesTakeTheVertexAsACorner) {
  const CovarianceMesh m = make_sample("cube");
  const Modelled r = split_edge(m, 0, 1);
  const MeshArrays a = arrays_of(r.mesh);
  EXPECT_EQ(a.n_faces(), 6);
  EXPECT_EQ(a.faces[0], (std::vector<int>{0, 3, 2, 1, 8}));
  EXPECT_EQ(a.faces[2], (std::vector<int>{0, 8, 1, 5, 4}));
  EXPECT_EQ(checked_boundary_edges(r.mesh), 0);
  EXPECT_EQ(r.summary, "split edge 0–1: 1 vertex, 0 faces added");
}

// With equal isotropic Gaussians the split mesh's GPS limit is plain Catmull-Clark's on its means;
// the split itself moves the limit surface (two quads become pentagons), measured at the old vertices.
TEST(SplitEdge, ActsAsPlainCatmullClarkOnEqualIsotropicGaussians) {
  const CovarianceMesh m = test::grid_mesh(6, 5);
  const Modelled r = split_edge(m, 9, 10);
  SubdivisionOptions o;
  o.levels = 2;
  o.limit = true;
  const std::vector<Vec3> linear = subdivide_points(r.mesh, o), gps = limit_means(r.mesh, 2);
  ASSERT_EQ(gps.size(), linear.size());
  const double diagonal = bounding_box_diagonal(m);
  double worst = 0;
  for (size_t v = 0; v < gps.size(); ++v) worst = std::max(worst, (gps[v] - linear[v]).norm());
  EXPECT_LE(worst, 1e-12 * diagonal);

  const std::vector<Vec3> unsplit = limit_means(m, 0), split = limit_means(r.mesh, 0);
  double moved = 0;
  for (size_t v = 0; v < m.n_vertices(); ++v) moved = std::max(moved, (split[v] - unsplit[v]).norm());
  moved /= diagonal;
  std::cout << "edge split: the old vertices' limits move by " << moved << " of the bounding-box diagonal\n";
  RecordProperty("limit_displacement_relative_to_diagonal", std::to_string(moved));
  EXPECT_GT(moved, 1e-6);
  EXPECT_LT(moved, 0.02);
}

TEST(SplitEdge, RefusalsNameTheEdgeAndChangeNothing) {
  const CovarianceMesh m = make_sample("cube");
  const MeshArrays before = arrays_of(m);
  EXPECT_EQ(error_of([&] { split_edge(m, 0, 6); }), "edge 0–6 is not in the mesh");
  EXPECT_EQ(error_of([&] { split_edge(m, 0, 9); }), "vertex 9 is not in the mesh (8 vertices)");
  EXPECT_EQ(error_of([&] { split_edge(m, 0, 1, 0.0); }), "the split fraction must be in (0, 1), got 0");
  EXPECT_EQ(error_of([&] { split_edge(m, 0, 1, 1.0); }), "the split fraction must be in (0, 1), got 1");
  EXPECT_EQ(error_of([&] { split_edge(m, 0, 1, std::numeric_limits<double>::quiet_NaN()); }),
            "the split fraction must be in (0, 1), got nan");
  expect_same_arrays(arrays_of(m), before);
}

TEST(FlipEdge, ReplacesTheDiagonal) {
  const CovarianceMesh m = test::triangle_grid_mesh(3, 2);
  const MeshArrays before = arrays_of(m);
  // Faces 2 {1, 2, 5} and 3 {2, 6, 5} share 2–5; the other diagonal is 1–6.
  const Modelled r = flip_edge(m, 2, 5);
  const MeshArrays a = arrays_of(r.mesh);
  EXPECT_EQ(a.n_vertices(), before.n_vertices());
  EXPECT_EQ(a.n_faces(), before.n_faces());
  EXPECT_EQ(a.means, before.means);
  EXPECT_TRUE(all_triangles(r.mesh));
  EXPECT_EQ(checked_boundary_edges(r.mesh), checked_boundary_edges(m));
  const DirectedEdges edges = directed_edges(a);
  EXPECT_FALSE(has_edge(edges, 2, 5));
  EXPECT_TRUE(has_edge(edges, 1, 6));
  EXPECT_EQ(r.selection, (std::vector<int>{1, 6}));
  EXPECT_EQ(r.summary, "flipped edge 2–5 to edge 1–6");
  for (int f = 0; f < a.n_faces(); ++f) {
    if (f == 2 || f == 3) continue;
    EXPECT_EQ(a.faces[size_t(f)], before.faces[size_t(f)]);
  }
  // Flipping back restores the edge.
  EXPECT_TRUE(has_edge(directed_edges(arrays_of(flip_edge(r.mesh, 6, 1).mesh)), 2, 5));
  expect_same_arrays(arrays_of(m), before);
}

TEST(FlipEdge, RefusalsNameTheEdgeAndChangeNothing) {
  const CovarianceMesh grid = test::triangle_grid_mesh(3, 2);
  const MeshArrays grid_before = arrays_of(grid);
  EXPECT_EQ(error_of([&] { flip_edge(grid, 0, 1); }), "edge 0–1 is on the boundary");
  EXPECT_EQ(error_of([&] { flip_edge(grid, 0, 5); }), "edge 0–5 is not in the mesh");
  expect_same_arrays(arrays_of(grid), grid_before);
  // Quads around the open cylinder's top fan: 16–17 lies between quad 8 and triangle 16.
  const CovarianceMesh mixed = test::open_cylinder_mesh();
  EXPECT_EQ(error_of([&] { flip_edge(mixed, 16, 17); }), "face 8 beside edge 16–17 is not a triangle");
  // Every flip of a tetrahedron would put a second edge between the two other corners.
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<std::vector<int>> faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  const CovarianceMesh tetrahedron = make_covariance_mesh(p, std::vector<Mat3>(4, 0.1 * Mat3::Identity()), faces);
  EXPECT_EQ(error_of([&] { flip_edge(tetrahedron, 0, 1); }), "flipping edge 0–1 would duplicate edge 2–3");
}

}  // namespace
}  // namespace gps
