#include "core/modelling/merge_vertices.h"

#include <gtest/gtest.h>

#include "core/support/error.h"
#include "core/modelling/samples.h"
#include "tests/support/error_of.h"
#include "tests/support/test_meshes.h"
#include "tests/support/mesh_checks.h"

namespace gps {
namespace {

using test::error_of;
using V = std::vector<int>;

using test::boundary_edges_of_oriented;

// A 2 × 2 grid (vertex j·3 + i) whose covariances differ from vertex to vertex.
CovarianceMesh varied_grid() {
  CovarianceMesh m = test::grid_mesh(2, 2);
  for (size_t v = 0; v < m.n_vertices(); ++v)
    m.set_covariance(v, Vec3(0.05 + 0.01 * double(v), 0.08, 0.03 + 0.02 * double(v)).asDiagonal());
  return m;
}

TEST(MergeVertices, CenterTakesTheMeanOfMeansAndTheCovarianceOfThe9DAverage) {
  const CovarianceMesh m = varied_grid();
  const Modelled r = merge_vertices(m, {5, 4}, MergePoint::center);
  EXPECT_EQ(r.selection, V{4});
  EXPECT_EQ(r.mesh.n_vertices(), 8u);
  EXPECT_EQ(r.mesh.n_faces(), 4u);
  const MeshArrays a = arrays_of(r.mesh);
  // Faces {1, 2, 5, 4} and {4, 5, 8, 7} lose a corner; vertices above 5 move down by one.
  EXPECT_EQ(a.faces[1], (V{1, 2, 4}));
  EXPECT_EQ(a.faces[3], (V{4, 7, 6}));
  EXPECT_EQ(a.faces[0], (V{0, 1, 4, 3}));
  EXPECT_TRUE(r.mesh.mean(4).isApprox(0.5 * (m.mean(4) + m.mean(5)), 1e-14));
  const MeshArrays in = arrays_of(m);
  const Gaussian blended = blend_gaussians(in, {{4, 0.5}, {5, 0.5}});
  const Dual average = 0.5 * (to_dual(m.mean(4), m.covariance(4)) + to_dual(m.mean(5), m.covariance(5)));
  EXPECT_TRUE(r.mesh.covariance(4).isApprox(blended.covariance, 1e-12));
  EXPECT_TRUE(r.mesh.covariance(4).isApprox(from_dual(average)->covariance, 1e-12));
  EXPECT_TRUE(r.mesh.mean(6).isApprox(m.mean(7), 0));
  EXPECT_EQ(r.mesh.covariance(7), m.covariance(8));
  EXPECT_EQ(boundary_edges_of_oriented(r.mesh), 8);
  EXPECT_EQ(r.summary, "merged 2 vertices into vertex 4");
}

TEST(MergeVertices, FirstAndLastTakeThatVertexsGaussian) {
  const CovarianceMesh m = varied_grid();
  const Modelled first = merge_vertices(m, {5, 4}, MergePoint::first);
  EXPECT_EQ(first.mesh.mean(4), m.mean(5));
  EXPECT_EQ(first.mesh.covariance(4), m.covariance(5));
  const Modelled last = merge_vertices(m, {5, 4}, MergePoint::last);
  EXPECT_EQ(last.mesh.mean(4), m.mean(4));
  EXPECT_EQ(last.mesh.covariance(4), m.covariance(4));
}

TEST(MergeVertices, CollapsingATriangleRemovesIt) {
  const CovarianceMesh ico = test::icosahedron_mesh();
  const MeshArrays a = arrays_of(ico);
  const V face = a.faces[0];
  const Modelled r = merge_vertices(ico, face, MergePoint::center);
  // Three vertices become one: the face and its three neighbours vanish (20 − 4), 2 vertices go.
  EXPECT_EQ(r.mesh.n_vertices(), 10u);
  EXPECT_EQ(r.mesh.n_faces(), 16u);
  EXPECT_EQ(boundary_edges_of_oriented(r.mesh), 0);
  EXPECT_EQ(r.summary, "merged 3 vertices into vertex " + std::to_string(r.selection[0]) + ", 4 faces removed");
}

TEST(MergeVertices, RefusalsNameTheElementAndChangeNothing) {
  const CovarianceMesh m = varied_grid();
  EXPECT_EQ(error_of([&] { merge_vertices(m, {4}, MergePoint::center); }), "merging needs at least 2 vertices");
  EXPECT_EQ(error_of([&] { merge_vertices(m, {4, 5, 4}, MergePoint::center); }), "vertex 4 is listed twice");
  EXPECT_EQ(error_of([&] {
              merge_vertices(m, {4, 9}, MergePoint::center);
            }),
            "vertex 9 is not in the mesh (9 vertices)");
  // Opposite corners of a quad: the face pinches into two slivers and is removed, as Blender does.
  const Modelled diagonal = merge_vertices(m, {0, 4}, MergePoint::center);
  EXPECT_EQ(diagonal.mesh.n_vertices(), 8u);
  EXPECT_EQ(diagonal.mesh.n_faces(), 3u);
  EXPECT_EQ(diagonal.summary, "merged 2 vertices into vertex 0, 1 face removed");
  // Two far corners: their faces would meet at one vertex only (two fans).
  const std::string pinch = error_of([&] { merge_vertices(m, {0, 8}, MergePoint::center); });
  EXPECT_NE(pinch.find("vertex 0"), std::string::npos) << pinch;
  EXPECT_NE(pinch.find("non-manifold"), std::string::npos) << pinch;
  EXPECT_EQ(m.n_vertices(), 9u);
  EXPECT_EQ(m.n_faces(), 4u);
}

// Opposite corners of a cube's face merged: the face is removed and the cube stays closed (7 vertices,
// 5 faces), as Blender's merge gives it.
TEST(MergeVertices, OppositeCornersOfAFaceCloseItUp) {
  const CovarianceMesh cube = make_sample("cube");
  const std::span<const int> face = cube.face(0);
  const Modelled r = merge_vertices(cube, {face[0], face[2]}, MergePoint::center);
  EXPECT_EQ(r.mesh.n_vertices(), 7u);
  EXPECT_EQ(r.mesh.n_faces(), 5u);
  EXPECT_EQ(boundary_edges_of_oriented(r.mesh), 0);
}

// A face met three times by the merged vertex is split into its loops; one met again after a loop
// closed is read as a new corner (no read past the loops found).
TEST(MergeVertices, AFaceMetManyTimesSplitsIntoItsLoops) {
  std::vector<Vec3> p;
  for (int i = 0; i < 8; ++i) p.emplace_back(std::cos(i * M_PI / 4), std::sin(i * M_PI / 4), 0.0);
  const CovarianceMesh octagon =
      make_covariance_mesh(p, std::vector<Mat3>(8, 0.01 * Mat3::Identity()), {{0, 1, 2, 3, 4, 5, 6, 7}});
  for (const std::vector<int>& group : {std::vector<int>{1, 3, 5}, std::vector<int>{2, 6}, std::vector<int>{1, 3}}) {
    const std::string what = error_of([&] {
      const Modelled r = merge_vertices(octagon, group, MergePoint::center);
      EXPECT_GE(r.mesh.n_faces(), 1u);
    });
    EXPECT_TRUE(what == "(accepted)" || what.find("vertex") != std::string::npos) << what;
  }
}

// Two unit quads side by side, each with its own copy of the shared edge (vertices 1, 2 and 4, 7).
CovarianceMesh two_quads(double gap) {
  const std::vector<Vec3> p = {{0, 0, 0},       {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                               {1 + gap, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1 + gap, 0}};
  std::vector<Mat3> c;
  for (int v = 0; v < 8; ++v) c.push_back(Vec3(0.1 + 0.01 * v, 0.1, 0.1 - 0.01 * v).asDiagonal());
  return make_covariance_mesh(p, c, {{0, 1, 2, 3}, {4, 5, 6, 7}});
}

TEST(WeldByDistance, CoincidentCopiesWeldIntoOneSheet) {
  const CovarianceMesh m = two_quads(1e-4);
  const Modelled r = weld_by_distance(m, {}, 1e-3);
  EXPECT_EQ(r.mesh.n_vertices(), 6u);
  EXPECT_EQ(r.mesh.n_faces(), 2u);
  EXPECT_EQ(r.selection, (V{1, 2}));
  EXPECT_EQ(r.summary, "welded 2 clusters: 2 vertices removed");
  const MeshArrays a = arrays_of(r.mesh);
  EXPECT_EQ(a.faces[1], (V{1, 4, 5, 2}));
  EXPECT_EQ(boundary_edges_of_oriented(r.mesh), 6);
  EXPECT_TRUE(r.mesh.mean(1).isApprox(0.5 * (m.mean(1) + m.mean(4)), 1e-15));
  const Gaussian blended = blend_gaussians(arrays_of(m), {{1, 0.5}, {4, 0.5}});
  EXPECT_TRUE(r.mesh.covariance(1).isApprox(blended.covariance, 1e-12));
  EXPECT_EQ(r.mesh.covariance(4), m.covariance(5));
}

TEST(WeldByDistance, OnlyTheGivenVerticesAndOnlyWithinTheDistance) {
  const CovarianceMesh m = two_quads(1e-4);
  const Modelled far = weld_by_distance(m, {}, 1e-5);
  EXPECT_EQ(far.mesh.n_vertices(), 8u);
  EXPECT_TRUE(far.selection.empty());
  EXPECT_EQ(far.summary, "welded 0 clusters: 0 vertices removed");
  const Modelled some = weld_by_distance(m, {1, 2, 4, 5, 7}, 1e-3);
  EXPECT_EQ(some.mesh.n_vertices(), 6u);
  EXPECT_EQ(some.selection, (V{1, 2}));
  // Welding one pair only (2 and 7 not offered) would pinch the quads together at a vertex.
  const std::string pinch = error_of([&] { weld_by_distance(m, {1, 4, 5}, 1e-3); });
  EXPECT_NE(pinch.find("vertex 1 is non-manifold"), std::string::npos) << pinch;
  EXPECT_EQ(weld_by_distance(m, {0, 1, 2, 3}, 1e-3).mesh.n_vertices(), 8u);
  // A sphere's vertices are far apart at this distance; a chain of near points forms one cluster.
  const CovarianceMesh sphere = make_sample("sphere", 1536);
  EXPECT_EQ(weld_by_distance(sphere, {}, 1e-3).mesh.n_vertices(), sphere.n_vertices());
}

TEST(WeldByDistance, Refusals) {
  const CovarianceMesh m = two_quads(1e-4);
  EXPECT_EQ(error_of([&] { weld_by_distance(m, {}, 0); }), "the distance must be positive and finite (got 0)");
  EXPECT_EQ(error_of([&] { weld_by_distance(m, {}, -1); }), "the distance must be positive and finite (got -1)");
  EXPECT_EQ(error_of([&] { weld_by_distance(m, {8}, 1); }), "vertex 8 is not in the mesh (8 vertices)");
  EXPECT_EQ(m.n_vertices(), 8u);
}

// Two copies of the same quad on top of each other (a duplicate left in place) weld into the one
// quad, as Blender's merge by distance gives it; so does a cube duplicated whole.
TEST(WeldByDistance, ADuplicateWeldedOntoItsOriginalIsOneFace) {
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const CovarianceMesh twice =
      make_covariance_mesh(p, std::vector<Mat3>(8, Mat3::Identity()), {{0, 1, 2, 3}, {5, 6, 7, 4}});
  const Modelled one = weld_by_distance(twice, {}, 1e-3);
  EXPECT_EQ(one.mesh.n_vertices(), 4u);
  EXPECT_EQ(one.mesh.n_faces(), 1u);
  EXPECT_EQ(one.summary, "welded 4 clusters: 4 vertices removed, 1 face removed");
  const CovarianceMesh cube = make_sample("cube");
  MeshArrays doubled = arrays_of(cube);
  for (size_t f = 0; f < cube.n_faces(); ++f) {
    std::vector<int> copy;
    for (const int v : cube.face(f)) copy.push_back(v + int(cube.n_vertices()));
    doubled.faces.push_back(copy);
  }
  for (size_t v = 0; v < cube.n_vertices(); ++v) doubled.add_vertex({cube.mean(v), cube.covariance(v)});
  const Modelled welded = weld_by_distance(build_mesh(doubled), {}, 1e-3);
  EXPECT_EQ(welded.mesh.n_vertices(), 8u);
  EXPECT_EQ(welded.mesh.n_faces(), 6u);
}

}  // namespace
}  // namespace gps
