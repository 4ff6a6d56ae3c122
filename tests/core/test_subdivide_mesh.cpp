// Subdividing as a modelling step: the whole mesh one GPS level finer keeps the exact limit surface
// (Catmull-Clark and Loop, anisotropic covariances); chosen faces split in 9D with their neighbours
// kept conforming (counts, faces' sizes, manifold and oriented, the new vertices' Gaussians).
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "core/modelling/samples.h"
#include "core/modelling/subdivide_mesh.h"
#include "core/reference/reference_subdivision.h"
#include "tests/support/error_of.h"
#include "tests/support/test_meshes.h"
#include "tests/support/mesh_checks.h"

namespace gps {
namespace {

using test::expect_same_arrays;

using test::error_of;

// Checks that every directed edge lies in one face at most (so an edge has at most two faces, each
// way once: manifold and consistently oriented); returns the number of boundary edges.
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

void expect_gaussian_near(const Gaussian& got, const Gaussian& want, double tol) {
  EXPECT_LE((got.mean - want.mean).norm(), tol * (1 + want.mean.norm()));
  EXPECT_LE((got.covariance - want.covariance).norm(), tol * want.covariance.norm());
}

std::vector<Vec3> limit_means(const CovarianceMesh& m, Scheme scheme, int levels) {
  SubdivisionOptions o;
  o.scheme = scheme;
  o.levels = levels;
  o.limit = true;
  const SubdivisionResult r = subdivide(m, o);
  std::vector<Vec3> p;
  for (size_t v = 0; v < r.mesh.n_vertices(); ++v) p.push_back(r.mesh.mean(v));
  return p;
}

// The limit positions of `m` at levels + 1 against those of subdivide_all(m) at `levels`: the
// reference numbers both the same way (the refined mesh is the reference's own first level).
double limit_difference(const CovarianceMesh& m, Scheme scheme, int levels) {
  const Modelled finer = subdivide_all(m);
  const std::vector<Vec3> want = limit_means(m, scheme, levels + 1);
  const std::vector<Vec3> got = limit_means(finer.mesh, scheme, levels);
  EXPECT_EQ(got.size(), want.size());
  double worst = 0;
  for (size_t v = 0; v < std::min(got.size(), want.size()); ++v) worst = std::max(worst, (got[v] - want[v]).norm());
  return worst / bounding_box_diagonal(m);
}

TEST(SubdivideAll, CatmullClarkKeepsTheLimitSurfaceOfAnisotropicMeshes) {
  for (const std::string name : {"cube", "cylinder"}) {
    const CovarianceMesh m = test::with_random_covariances(make_sample(name), 7);
    for (int levels : {0, 1, 2}) {
      const double d = limit_difference(m, Scheme::catmull_clark, levels);
      EXPECT_LE(d, 1e-12) << name << " at level " << levels;
    }
  }
}

TEST(SubdivideAll, LoopKeepsTheLimitSurfaceOfAnisotropicMeshes) {
  for (const CovarianceMesh& m : {test::with_random_covariances(make_sample("icosphere", 20), 3),
                                  test::with_random_covariances(test::triangle_grid_mesh(4, 3), 5)})
    for (int levels : {0, 1, 2}) EXPECT_LE(limit_difference(m, Scheme::loop, levels), 1e-12) << "level " << levels;
}

TEST(SubdivideAll, CountsSchemeAndSelection) {
  const Modelled cube = subdivide_all(make_sample("cube"));
  EXPECT_EQ(cube.mesh.n_vertices(), 26u);
  EXPECT_EQ(cube.mesh.n_faces(), 24u);
  EXPECT_TRUE(cube.selection.empty());
  EXPECT_EQ(checked_boundary_edges(cube.mesh), 0);
  EXPECT_EQ(cube.summary, "subdivided the whole mesh (Catmull-Clark): 26 vertices, 24 faces");
  const Modelled ico = subdivide_all(test::icosahedron_mesh());
  EXPECT_EQ(ico.mesh.n_vertices(), 42u);
  EXPECT_EQ(ico.mesh.n_faces(), 80u);
  for (const auto& f : arrays_of(ico.mesh).faces) EXPECT_EQ(f.size(), 3u);
  EXPECT_EQ(ico.summary, "subdivided the whole mesh (Loop): 42 vertices, 80 faces");
}

TEST(SubdivideFaces, OneFaceOfTheCube) {
  const CovarianceMesh m = test::with_random_covariances(make_sample("cube"), 11);
  const MeshArrays before = arrays_of(m);
  const Modelled r = subdivide_faces(m, {0});
  const MeshArrays a = arrays_of(r.mesh);
  ASSERT_EQ(a.n_vertices(), 8 + 5);  // the face point, four edge midpoints
  ASSERT_EQ(a.n_faces(), 6 + 3);
  EXPECT_EQ(checked_boundary_edges(r.mesh), 0);
  std::vector<size_t> sizes;
  for (const auto& f : a.faces) sizes.push_back(f.size());
  // Face 0 and its appended pieces quads, the four neighbours pentagons, the opposite face a quad.
  EXPECT_EQ(sizes, (std::vector<size_t>{4, 4, 5, 5, 5, 5, 4, 4, 4}));
  // Face 0 = {0, 3, 2, 1}: the face point first, then the midpoints of 0–3, 3–2, 2–1, 1–0.
  EXPECT_EQ(a.faces[0], (std::vector<int>{0, 9, 8, 12}));
  expect_gaussian_near(a.gaussian(8), face_point(before, 0), 1e-14);
  const int ends[4][2] = {{0, 3}, {3, 2}, {2, 1}, {1, 0}};
  for (int k = 0; k < 4; ++k)
    expect_gaussian_near(a.gaussian(9 + k), blend_gaussians(before, {{ends[k][0], 0.5}, {ends[k][1], 0.5}}), 1e-14);
  for (int v = 0; v < 8; ++v) EXPECT_EQ(a.gaussian(v).mean, before.gaussian(v).mean);
  EXPECT_EQ(r.selection, (std::vector<int>{0, 1, 2, 3, 8, 9, 10, 11, 12}));
  EXPECT_EQ(r.summary, "subdivided 1 face: 5 vertices, 3 faces added");
  expect_same_arrays(arrays_of(m), before);
}

TEST(SubdivideFaces, EqualIsotropicCovariancesGiveTheLinearMidpoints) {
  const CovarianceMesh m = test::prism_mesh();
  const Modelled r = subdivide_faces(m, {0, 3});
  const MeshArrays a = arrays_of(r.mesh);
  EXPECT_EQ(checked_boundary_edges(r.mesh), 0);
  // Face 0 (the pentagon 4 3 2 1 0): its face point, then its midpoints; face 3's are all but 1–2 new.
  Vec3 centre = Vec3::Zero();
  for (int v : {0, 1, 2, 3, 4}) centre += m.mean(size_t(v)) / 5.0;
  EXPECT_LE((a.means[10] - centre).norm(), 1e-15 * 8);
  EXPECT_LE((a.means[11] - 0.5 * (m.mean(4) + m.mean(3))).norm(), 1e-15 * 8);
  for (int v = 10; v < a.n_vertices(); ++v)
    EXPECT_LE((a.covariances[size_t(v)] - m.covariance(0)).norm(), 1e-15 * 8 * m.covariance(0).norm());
  EXPECT_EQ(a.n_vertices(), 10 + 6 + 1 + 3);
  EXPECT_EQ(a.n_faces(), 7 + 4 + 3);
}

TEST(SubdivideFaces, ATriangleMeshStaysTriangles) {
  const CovarianceMesh m = test::with_random_covariances(test::icosahedron_mesh(), 2);
  // One triangle: 1 → 4, its three neighbours 1 → 2.
  const Modelled one = subdivide_faces(m, {0});
  EXPECT_EQ(one.mesh.n_vertices(), 12u + 3u);
  EXPECT_EQ(one.mesh.n_faces(), 20u + 3u + 3u);
  EXPECT_EQ(one.selection, (std::vector<int>{0, 5, 11, 12, 13, 14}));
  // Faces 0 {0, 11, 5} and 2 {0, 1, 7} share no edge: face 1 {0, 5, 1} between them has two split
  // edges (3 triangles), four other neighbours one each.
  const Modelled two = subdivide_faces(m, {2, 0});
  EXPECT_EQ(two.mesh.n_vertices(), 12u + 6u);
  EXPECT_EQ(two.mesh.n_faces(), 20u + 2 * 3u + 2u + 4u);
  // A face whose three neighbours are chosen splits 1 → 4 as well.
  const Modelled ring = subdivide_faces(m, {0, 2, 5});  // the neighbours of face 1 across 0–5, 1–0, 5–1
  EXPECT_EQ(ring.mesh.n_faces(), 20u + 3 * 3u + 3u + 2 * 1u + 2 * 1u + 2 * 1u);
  for (const Modelled* r : {&one, &two, &ring}) {
    EXPECT_EQ(checked_boundary_edges(r->mesh), 0);
    for (const auto& f : arrays_of(r->mesh).faces) EXPECT_EQ(f.size(), 3u);
  }
  // On an open triangle grid the boundary grows by the split boundary edges.
  const CovarianceMesh grid = test::triangle_grid_mesh(3, 2);
  const Modelled g = subdivide_faces(grid, {2});  // {1, 2, 5}: its edge 1–2 is on the boundary
  EXPECT_EQ(checked_boundary_edges(g.mesh), checked_boundary_edges(grid) + 1);
  for (const auto& f : arrays_of(g.mesh).faces) EXPECT_EQ(f.size(), 3u);
}

TEST(SubdivideFaces, RefusalsNameTheFaceAndChangeNothing) {
  const CovarianceMesh m = make_sample("cube");
  const MeshArrays before = arrays_of(m);
  EXPECT_EQ(error_of([&] { subdivide_faces(m, {}); }), "no faces to subdivide");
  EXPECT_EQ(error_of([&] { subdivide_faces(m, {2, 6}); }), "face 6 is not in the mesh (6 faces)");
  EXPECT_EQ(error_of([&] { subdivide_faces(m, {-1}); }), "face -1 is not in the mesh (6 faces)");
  expect_same_arrays(arrays_of(m), before);
}

}  // namespace
}  // namespace gps
