#include "core/modelling/delete_elements.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "core/modelling/loop_cut.h"
#include "core/modelling/samples.h"
#include "tests/support/error_of.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

using test::error_of;

/// Counts of a mesh, whether every directed edge appears once, and its boundary loops' lengths (sorted).
struct LoopedShape {
  int vertices = 0, edges = 0, faces = 0;
  bool oriented = true;
  std::vector<int> boundary_loops;
  int euler() const { return vertices - edges + faces; }
};

LoopedShape looped_shape_of(const CovarianceMesh& mesh) {
  const MeshArrays a = arrays_of(mesh);
  std::map<std::pair<int, int>, int> directed;
  for (const auto& face : a.faces)
    for (size_t k = 0; k < face.size(); ++k) ++directed[{face[k], face[(k + 1) % face.size()]}];
  LoopedShape s;
  s.vertices = a.n_vertices();
  s.faces = a.n_faces();
  std::set<std::pair<int, int>> undirected;
  std::map<int, int> boundary_next;
  for (const auto& [e, n] : directed) {
    s.oriented = s.oriented && n == 1;
    undirected.insert({std::min(e.first, e.second), std::max(e.first, e.second)});
    if (!directed.count({e.second, e.first})) boundary_next[e.first] = e.second;
  }
  s.edges = int(undirected.size());
  std::set<int> seen;
  for (const auto& [start, next] : boundary_next) {
    if (seen.count(start)) continue;
    int length = 0;
    for (int v = start; seen.insert(v).second; v = boundary_next.at(v)) ++length;
    s.boundary_loops.push_back(length);
  }
  std::sort(s.boundary_loops.begin(), s.boundary_loops.end());
  return s;
}

void expect_unchanged(const CovarianceMesh& mesh, const MeshArrays& before) {
  const MeshArrays after = arrays_of(mesh);
  EXPECT_EQ(after.means, before.means);
  EXPECT_EQ(after.covariances, before.covariances);
  EXPECT_EQ(after.faces, before.faces);
}

TEST(DeleteFaces, ACubeFaceLeavesOneBoundaryLoopOfFourEdges) {
  const CovarianceMesh cube = make_sample("cube");
  const Modelled m = delete_faces(cube, {0});
  const LoopedShape s = looped_shape_of(m.mesh);
  EXPECT_EQ(s.vertices, 8);
  EXPECT_EQ(s.faces, 5);
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(s.boundary_loops, (std::vector<int>{4}));
  EXPECT_EQ(s.euler(), 1);
  EXPECT_TRUE(m.selection.empty());
  EXPECT_EQ(m.summary, "deleted 1 face");
  EXPECT_EQ(arrays_of(m.mesh).faces[0], (std::vector<int>{4, 5, 6, 7}));  // the rest compact in order
}

TEST(DeleteFaces, FacesAroundACornerTakeTheCornerVertexWithThem) {
  const CovarianceMesh cube = make_sample("cube");
  const MeshArrays before = arrays_of(cube);
  const Modelled m = delete_faces(cube, {5, 0, 2});  // the three faces at vertex 0
  const LoopedShape s = looped_shape_of(m.mesh);
  EXPECT_EQ(s.vertices, 7);
  EXPECT_EQ(s.faces, 3);
  EXPECT_EQ(s.boundary_loops, (std::vector<int>{6}));
  EXPECT_EQ(m.summary, "deleted 3 faces: 1 vertex removed");
  const MeshArrays a = arrays_of(m.mesh);
  for (int v = 0; v < 7; ++v) EXPECT_EQ(a.means[size_t(v)], before.means[size_t(v + 1)]);
  EXPECT_EQ(a.faces[0], (std::vector<int>{3, 4, 5, 6}));  // input face 1 {4, 5, 6, 7}
}

TEST(DeleteFaces, RefusesANonManifoldOrEmptyResult) {
  const CovarianceMesh grid = test::flat_grid(2, 2, 0.01);
  const MeshArrays before = arrays_of(grid);
  EXPECT_EQ(error_of([&] {
              delete_faces(grid, {1, 2});
            }),
            "the result would be non-manifold at vertex 4 (2 fans of faces would meet only there)");
  EXPECT_EQ(error_of([&] { delete_faces(grid, {0, 1, 2, 3}); }), "the result would have no faces");
  EXPECT_EQ(error_of([&] { delete_faces(grid, {4}); }), "face 4 is not in the mesh (4 faces)");
  expect_unchanged(grid, before);

  // Vertex 3 goes with face 2, but the refusal names vertex 6 by its index in the input.
  const CovarianceMesh big = test::flat_grid(3, 3, 0.01);
  EXPECT_EQ(error_of([&] {
              delete_faces(big, {2, 4, 6});
            }),
            "the result would be non-manifold at vertex 6 (2 fans of faces would meet only there)");
}

TEST(DeleteVertices, AVertexTakesItsFaces) {
  const CovarianceMesh grid = test::flat_grid(4, 4, 0.01);
  const Modelled m = delete_vertices(grid, {12});  // the centre: a square hole
  const LoopedShape s = looped_shape_of(m.mesh);
  EXPECT_EQ(s.vertices, 24);
  EXPECT_EQ(s.faces, 12);
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(s.boundary_loops, (std::vector<int>{8, 16}));
  EXPECT_EQ(m.summary, "deleted 1 vertex: 4 faces, 1 vertex removed");
  EXPECT_TRUE(m.selection.empty());

  const Modelled corner = delete_vertices(make_sample("cube"), {0});
  EXPECT_EQ(corner.mesh.n_vertices(), 7u);
  EXPECT_EQ(corner.mesh.n_faces(), 3u);
  EXPECT_EQ(error_of([&] { delete_vertices(grid, {25}); }), "vertex 25 is not in the mesh (25 vertices)");
}

TEST(DeleteEdges, AnEdgeTakesTheFacesOnBothSides) {
  const CovarianceMesh cube = make_sample("cube");
  const MeshArrays before = arrays_of(cube);
  const Modelled m = delete_edges(cube, {{1, 0}});
  const LoopedShape s = looped_shape_of(m.mesh);
  EXPECT_EQ(s.vertices, 8);
  EXPECT_EQ(s.faces, 4);
  EXPECT_EQ(s.boundary_loops, (std::vector<int>{6}));
  EXPECT_EQ(m.summary, "deleted 1 edge: 2 faces removed");
  EXPECT_EQ(error_of([&] { delete_edges(cube, {{0, 6}}); }), "edge 0–6 is not in the mesh");
  expect_unchanged(cube, before);
}

// Cube faces 1 {4, 5, 6, 7} and 2 {0, 1, 5, 4} share edge 4–5. Its ends are then left between two
// edges in a line, which Blender's Dissolve Edges joins: the cube becomes a prism of 6 vertices, its
// two sides beside the edge triangles.
TEST(DissolveEdges, TwoFacesMergeIntoOneWithCornersInOrder) {
  const CovarianceMesh cube = make_sample("cube");
  const Modelled m = dissolve_edges(cube, {{4, 5}});
  const LoopedShape s = looped_shape_of(m.mesh);
  EXPECT_EQ(s.vertices, 6);
  EXPECT_EQ(s.faces, 5);
  EXPECT_EQ(s.euler(), 2);
  EXPECT_TRUE(s.oriented);
  EXPECT_TRUE(s.boundary_loops.empty());
  EXPECT_EQ(m.summary, "dissolved 1 edge: 1 face, 2 vertices removed");
  const MeshArrays a = arrays_of(m.mesh);  // vertices 6 and 7 are now 4 and 5
  EXPECT_EQ(a.faces, (std::vector<std::vector<int>>{{0, 3, 2, 1}, {0, 1, 4, 5}, {2, 3, 5, 4}, {1, 2, 4}, {0, 5, 3}}));
}

TEST(DissolveEdges, AChainOfEdgesMergesARowOfFaces) {
  const CovarianceMesh row = test::flat_grid(3, 1, 0.01);  // vertices 0..3 below, 4..7 above
  const Modelled m = dissolve_edges(row, {{2, 6}, {1, 5}});
  EXPECT_EQ(arrays_of(m.mesh).faces, (std::vector<std::vector<int>>{{0, 1, 2, 3, 7, 6, 5, 4}}));
  EXPECT_EQ(looped_shape_of(m.mesh).boundary_loops, (std::vector<int>{8}));
}

TEST(DissolveEdges, EveryEdgeAroundAVertexLeavesOnePolygonWithoutIt) {
  const CovarianceMesh grid = test::flat_grid(3, 3, 0.01);
  const Modelled m = dissolve_edges(grid, {{5, 1}, {5, 4}, {5, 6}, {5, 9}});
  const LoopedShape s = looped_shape_of(m.mesh);
  EXPECT_EQ(s.vertices, 15);
  EXPECT_EQ(s.faces, 6);
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(s.euler(), 1);
  EXPECT_EQ(arrays_of(m.mesh).faces[0], (std::vector<int>{0, 1, 2, 5, 9, 8, 7, 4}));
}

TEST(DissolveEdges, RefusesBoundaryEdgesAndRepeatedVertices) {
  const CovarianceMesh cube = make_sample("cube");
  const MeshArrays before = arrays_of(cube);
  // Faces 1, 2 and 4 meet pairwise at edges 4–5, 5–6 and 1–5: merging all three leaves 1–5 hanging
  // inside the merged face, which passes vertex 1 twice.
  EXPECT_EQ(error_of([&] { dissolve_edges(cube, {{4, 5}, {5, 6}}); }), "the merged face 1 would have vertex 1 twice");
  EXPECT_EQ(error_of([&] { dissolve_edges(cube, {{0, 7}}); }), "edge 0–7 is not in the mesh");
  expect_unchanged(cube, before);
  const CovarianceMesh grid = test::flat_grid(2, 2, 0.01);
  EXPECT_EQ(error_of([&] { dissolve_edges(grid, {{0, 1}}); }), "edge 0–1 is on the boundary");
}

TEST(DissolveVertices, AnInteriorVertexMergesItsFacesInOrder) {
  const CovarianceMesh grid = test::flat_grid(3, 3, 0.01);
  const Modelled m = dissolve_vertices(grid, {5});
  const LoopedShape s = looped_shape_of(m.mesh);
  EXPECT_EQ(s.vertices, 15);
  EXPECT_EQ(s.faces, 6);
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(s.euler(), 1);
  EXPECT_EQ(s.boundary_loops, (std::vector<int>{12}));
  EXPECT_EQ(m.summary, "dissolved 1 vertex: 3 faces, 1 vertex removed");
  EXPECT_TRUE(m.selection.empty());
  EXPECT_EQ(arrays_of(m.mesh).faces[0], (std::vector<int>{0, 1, 2, 5, 9, 8, 7, 4}));

  const Modelled corner = dissolve_vertices(make_sample("cube"), {0});
  const LoopedShape c = looped_shape_of(corner.mesh);
  EXPECT_EQ(c.vertices, 7);
  EXPECT_EQ(c.faces, 4);
  EXPECT_EQ(c.euler(), 2);
  EXPECT_TRUE(c.oriented);
  EXPECT_TRUE(c.boundary_loops.empty());
}

TEST(DissolveVertices, ABoundaryVertexOfOneFaceIsRemovedFromIt) {
  const CovarianceMesh grid = test::flat_grid(2, 2, 0.01);
  const Modelled m = dissolve_vertices(grid, {0});
  EXPECT_EQ(m.mesh.n_vertices(), 8u);
  EXPECT_EQ(arrays_of(m.mesh).faces[0], (std::vector<int>{0, 3, 2}));  // input {1, 4, 3}
  EXPECT_EQ(looped_shape_of(m.mesh).boundary_loops, (std::vector<int>{7}));
}

TEST(DissolveVertices, Refusals) {
  const CovarianceMesh grid = test::flat_grid(2, 2, 0.01);
  const MeshArrays before = arrays_of(grid);
  EXPECT_EQ(error_of([&] { dissolve_vertices(grid, {1}); }),
            "vertex 1 is on the boundary of 2 faces (only a boundary vertex of a single face can be dissolved)");
  EXPECT_EQ(error_of([&] { dissolve_vertices(grid, {9}); }), "vertex 9 is not in the mesh (9 vertices)");
  expect_unchanged(grid, before);
  const CovarianceMesh triangle =
      make_covariance_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, std::vector<Mat3>(3, Mat3::Identity()), {{0, 1, 2}});
  EXPECT_EQ(error_of([&] { dissolve_vertices(triangle, {0}); }), "face 0 would be left with 2 corners");
}

}  // namespace
}  // namespace gps

namespace gps {
namespace {

TEST(DissolveVertices, ALoopCutsVerticesGiveBackTheFacesItCut) {
  // As in Blender: the edges along the loop go first, then each vertex left between two edges in a line.
  const CovarianceMesh cube = make_sample("cube");
  const std::span<const int> face = cube.face(0);
  const Modelled cut = loop_cut(cube, face[0], face[1], 1);
  ASSERT_EQ(cut.selection.size(), 4u);
  const Modelled back = dissolve_vertices(cut.mesh, cut.selection);
  const LoopedShape s = looped_shape_of(back.mesh);
  EXPECT_EQ(s.vertices, 8);
  EXPECT_EQ(s.faces, 6);
  EXPECT_TRUE(s.oriented);
  EXPECT_TRUE(s.boundary_loops.empty());
  for (size_t f = 0; f < back.mesh.n_faces(); ++f) EXPECT_EQ(back.mesh.face(f).size(), 4u) << f;
  for (size_t v = 0; v < 8; ++v) EXPECT_EQ(back.mesh.mean(v), cube.mean(v)) << v;
  // Its edges dissolved instead: the same, as Blender's Dissolve Edges gives it.
  std::vector<std::array<int, 2>> ring;
  for (size_t i = 0; i < 4; ++i) ring.push_back({cut.selection[i], cut.selection[(i + 1) % 4]});
  std::vector<std::array<int, 2>> along;  // the loop's edges: those joining two of its vertices
  const MeshArrays cut_arrays = arrays_of(cut.mesh);
  for (const auto& face : cut_arrays.faces)
    for (size_t k = 0; k < face.size(); ++k) {
      const int x = face[k], y = face[(k + 1) % face.size()];
      const auto in_loop = [&](int v) { return std::count(cut.selection.begin(), cut.selection.end(), v) > 0; };
      if (x < y && in_loop(x) && in_loop(y)) along.push_back({x, y});
    }
  ASSERT_EQ(along.size(), 4u);
  const LoopedShape edges = looped_shape_of(dissolve_edges(cut.mesh, along).mesh);
  EXPECT_EQ(edges.vertices, 8);
  EXPECT_EQ(edges.faces, 6);
  EXPECT_TRUE(edges.oriented);
  // One of them alone has four edges: its four faces merge.
  const Modelled one = dissolve_vertices(cut.mesh, {cut.selection[0]});
  EXPECT_EQ(looped_shape_of(one.mesh).faces, 7);
  EXPECT_EQ(looped_shape_of(one.mesh).vertices, 11);
  // A vertex between two edges in a line, alone: its two faces keep apart, without it.
  const CovarianceMesh two =
      make_covariance_mesh({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}, {1, 0.5, 0}},
                           std::vector<Mat3>(7, 0.01 * Mat3::Identity()), {{0, 1, 6, 4, 3}, {1, 2, 5, 4, 6}});
  const Modelled line = dissolve_vertices(two, {6});
  EXPECT_EQ(arrays_of(line.mesh).faces, (std::vector<std::vector<int>>{{0, 1, 4, 3}, {1, 2, 5, 4}}));
}

}  // namespace
}  // namespace gps
