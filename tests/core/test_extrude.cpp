#include "core/modelling/extrude.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "core/modelling/samples.h"
#include "tests/support/error_of.h"
#include "tests/support/mesh_checks.h"

namespace gps {
namespace {

using test::Shape;
using test::shape_of;

using test::error_of;

void expect_same(const MeshArrays& x, const MeshArrays& y) {
  EXPECT_EQ(x.means, y.means);
  EXPECT_EQ(x.covariances, y.covariances);
  EXPECT_EQ(x.faces, y.faces);
}

// The cube's face 1 is its +z face (corners 4, 5, 6, 7 at z = 1).
TEST(ExtrudeFaces, OneCubeFaceAddsFourVerticesAndFourQuads) {
  const CovarianceMesh cube = make_sample("cube");
  const MeshArrays before = arrays_of(cube);
  const double d = 0.37;
  const Modelled m = extrude_faces(cube, {1}, d);
  const Shape s = shape_of(m.mesh), s0 = shape_of(cube);
  EXPECT_EQ(s.vertices, 12);
  EXPECT_EQ(s.faces, 10);
  EXPECT_EQ(s.euler(), s0.euler());
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(s.boundary_edges, 0);
  EXPECT_EQ(m.selection, (std::vector<int>{8, 9, 10, 11}));
  EXPECT_EQ(m.summary, "extruded 1 face: 4 vertices, 4 faces added");

  const MeshArrays a = arrays_of(m.mesh);
  EXPECT_EQ(a.faces[1], (std::vector<int>{8, 9, 10, 11}));
  for (int k = 0; k < 4; ++k) {
    const int v = 4 + k, copy = 8 + k;
    EXPECT_EQ(a.means[size_t(v)], before.means[size_t(v)]);  // the originals stay
    EXPECT_EQ(a.means[size_t(copy)].z(), before.means[size_t(v)].z() + d);
    EXPECT_EQ(a.means[size_t(copy)].x(), before.means[size_t(v)].x());
    EXPECT_EQ(a.means[size_t(copy)].y(), before.means[size_t(v)].y());
    EXPECT_EQ(a.covariances[size_t(copy)], before.covariances[size_t(v)]);
  }
  // The first side quad joins edge 4 → 5 to its copy.
  EXPECT_EQ(a.faces[6], (std::vector<int>{4, 5, 9, 8}));
  expect_same(arrays_of(cube), before);
}

// On a mesh of triangles the band is triangles too, so the mesh stays Loop's: one of the cone's
// triangles adds 3 vertices and 6 triangles; its open bottom's 8 edges add 8 vertices and 16.
TEST(ExtrudeFaces, ATriangleMeshStaysATriangleMesh) {
  const CovarianceMesh cone = make_sample("cone");
  const Shape s0 = shape_of(cone);
  const Modelled face = extrude_faces(cone, {0}, 0.2);
  const Shape s = shape_of(face.mesh);
  EXPECT_EQ(s.vertices, s0.vertices + 3);
  EXPECT_EQ(s.faces, s0.faces + 6);
  EXPECT_EQ(s.euler(), s0.euler());
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(face.summary, "extruded 1 face: 3 vertices, 6 faces added");
  for (const auto& f : arrays_of(face.mesh).faces) EXPECT_EQ(f.size(), 3u);

  std::vector<int> rim;
  for (size_t v = 0; v < cone.n_vertices(); ++v)
    if (cone.is_boundary_vertex(v)) rim.push_back(int(v));
  ASSERT_EQ(rim.size(), 8u);
  const Modelled edges = extrude_vertices(cone, rim, Vec3(0, 0, -0.5));
  EXPECT_EQ(shape_of(edges.mesh).faces, s0.faces + 16);
  EXPECT_TRUE(shape_of(edges.mesh).oriented);
  for (const auto& f : arrays_of(edges.mesh).faces) EXPECT_EQ(f.size(), 3u);
  // A mixed mesh keeps its quads: the cube's band is quads, as above.
  for (const auto& f : arrays_of(extrude_faces(make_sample("cube"), {1}, 0.5).mesh).faces) EXPECT_EQ(f.size(), 4u);
}

TEST(ExtrudeFaces, TwoAdjacentCubeFacesMoveAlongTheirAverageNormal) {
  const CovarianceMesh cube = make_sample("cube");
  const MeshArrays before = arrays_of(cube);
  const Modelled m = extrude_faces(cube, {4, 1}, 1.0);  // +x and +z faces, sharing edge 5–6
  const Shape s = shape_of(m.mesh);
  EXPECT_EQ(s.vertices, 14);
  EXPECT_EQ(s.faces, 12);
  EXPECT_EQ(s.euler(), 2);
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(s.boundary_edges, 0);
  EXPECT_EQ(m.selection, (std::vector<int>{8, 9, 10, 11, 12, 13}));
  const MeshArrays a = arrays_of(m.mesh);
  const Vec3 shift = Vec3(1, 0, 1) / std::sqrt(2.0);
  const std::vector<int> originals = {1, 2, 4, 5, 6, 7};
  for (size_t k = 0; k < originals.size(); ++k)
    EXPECT_LT((a.means[8 + k] - before.means[size_t(originals[k])] - shift).norm(), 1e-15);
}

// Faces 3 and 4 of the 4 × 4 grid share edge 8–9 (inside the region) and have 3–4 on the border
// of the region; both creased, with a corner at 9.
TEST(ExtrudeFaces, CreasesAndCornersTravelWithTheRegionAndStayAtItsBase) {
  CovarianceMesh grid = make_sample("grid", 16);
  grid.sharpness.set_crease(8, 9, 10.0);
  grid.sharpness.set_crease(3, 4, 2.5);
  grid.sharpness.set_crease(0, 1, 1.0);  // outside the region
  grid.sharpness.set_corner(9, 4.0, int(grid.n_vertices()));
  const Modelled m = extrude_faces(grid, {3, 7}, 0.5);
  const MeshArrays a = arrays_of(m.mesh);
  ASSERT_EQ(a.sharpness.corners.size(), size_t(a.n_vertices()));
  // The copy of each region vertex is the one the region's faces now use.
  std::map<int, int> copy;
  const MeshArrays before = arrays_of(grid);
  for (int f : {3, 7})
    for (size_t k = 0; k < before.faces[size_t(f)].size(); ++k)
      copy[before.faces[size_t(f)][k]] = a.faces[size_t(f)][k];
  EXPECT_NE(copy.at(8), 8);
  EXPECT_EQ(a.sharpness.crease(copy.at(8), copy.at(9)), 10.0);  // on the cap
  EXPECT_EQ(a.sharpness.crease(copy.at(3), copy.at(4)), 2.5);
  EXPECT_EQ(a.sharpness.crease(3, 4), 2.5);  // and at the base, where the edge also stays
  EXPECT_EQ(a.sharpness.crease(8, 9), 0.0);  // inside the region: no longer an edge at the base
  EXPECT_EQ(a.sharpness.crease(0, 1), 1.0);
  EXPECT_EQ(a.sharpness.corner(copy.at(9)), 4.0);
  EXPECT_EQ(a.sharpness.corner(9), 4.0);
  EXPECT_EQ(a.sharpness.corner(copy.at(8)), 0.0);
}

TEST(ExtrudeFaces, FaceOnAGridBorderKeepsTheBoundary) {
  const CovarianceMesh grid = make_sample("grid", 16);  // 4 × 4 quads, 25 vertices
  const Shape s0 = shape_of(grid);
  const Modelled m = extrude_faces(grid, {0}, 0.5);
  const Shape s = shape_of(m.mesh);
  EXPECT_EQ(s.vertices, 29);
  EXPECT_EQ(s.faces, 20);
  EXPECT_EQ(s.euler(), s0.euler());
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(s.boundary_edges, s0.boundary_edges);
}

TEST(ExtrudeFaces, InnerVerticesOfARegionMoveInsteadOfBeingCopied) {
  const CovarianceMesh grid = make_sample("grid", 16);
  const MeshArrays before = arrays_of(grid);
  const Modelled m = extrude_faces(grid, {5, 6, 9, 10}, 0.25);  // the 2 × 2 block around vertex 12
  const Shape s = shape_of(m.mesh);
  EXPECT_EQ(s.vertices, 25 + 8);
  EXPECT_EQ(s.faces, 16 + 8);
  EXPECT_EQ(s.euler(), 1);
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(m.selection.size(), 9u);
  EXPECT_EQ(m.selection[0], 12);
  const MeshArrays a = arrays_of(m.mesh);
  EXPECT_GT((a.means[12] - before.means[12]).norm(), 0.2);
  EXPECT_LT(std::abs((a.means[12] - before.means[12]).norm() - 0.25), 1e-12);
  EXPECT_EQ(a.covariances[12], before.covariances[12]);
}

TEST(ExtrudeFaces, DiagonalFacesGetOneCopyPerFanAtTheirSharedVertex) {
  const CovarianceMesh grid = make_sample("grid", 4);  // 2 × 2 quads around vertex 4
  const Modelled m = extrude_faces(grid, {0, 3}, 0.1);
  const Shape s = shape_of(m.mesh);
  EXPECT_EQ(s.vertices, 9 + 8);
  EXPECT_EQ(s.faces, 4 + 8);
  EXPECT_TRUE(s.oriented);
}

TEST(ExtrudeFaces, DistanceZeroIsAllowed) {
  const Modelled m = extrude_faces(make_sample("cube"), {1}, 0.0);
  const MeshArrays a = arrays_of(m.mesh);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(a.means[size_t(8 + k)], a.means[size_t(4 + k)]);
}

TEST(ExtrudeFaces, RefusalsNameTheProblemAndChangeNothing) {
  const CovarianceMesh cube = make_sample("cube");
  const MeshArrays before = arrays_of(cube);
  EXPECT_EQ(error_of([&] { extrude_faces(cube, {6}, 1.0); }), "face 6 is not in the mesh (6 faces)");
  EXPECT_EQ(error_of([&] { extrude_faces(cube, {-1}, 1.0); }), "face -1 is not in the mesh (6 faces)");
  EXPECT_EQ(error_of([&] { extrude_faces(cube, {}, 1.0); }), "no faces are selected");
  EXPECT_EQ(error_of([&] {
              extrude_faces(cube, {0, 1, 2, 3, 4, 5}, 1.0);
            }),
            "extruding every face of a closed part would leave nothing to join");
  EXPECT_EQ(error_of([&] { extrude_faces(cube, {0}, std::nan("")); }), "distance nan is not finite");
  EXPECT_EQ(error_of([&] {
              extrude_faces(cube, {0, 1}, 1.0);
            }),
            "the faces' normals cancel out, so there is no direction to extrude along");
  expect_same(arrays_of(cube), before);
}

// The grid's first row of vertices is 0..4, on its boundary; its faces run counter-clockwise.
TEST(ExtrudeEdges, BoundaryEdgesOfAGridGetQuadsOrientedLikeTheirFaces) {
  const CovarianceMesh grid = make_sample("grid", 16);
  const MeshArrays before = arrays_of(grid);
  const Vec3 offset(0, -0.5, 0.1);
  const Modelled m = extrude_edges(grid, {{1, 0}, {1, 2}, {0, 1}}, offset);
  const Shape s = shape_of(m.mesh), s0 = shape_of(grid);
  EXPECT_EQ(s.vertices, 28);
  EXPECT_EQ(s.faces, 18);
  EXPECT_EQ(s.euler(), s0.euler());
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(s.boundary_edges, s0.boundary_edges + 2);
  EXPECT_EQ(m.selection, (std::vector<int>{25, 26, 27}));
  EXPECT_EQ(m.summary, "extruded 2 edges: 3 vertices, 2 faces added");
  const MeshArrays a = arrays_of(m.mesh);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(a.means[size_t(25 + k)], before.means[size_t(k)] + offset);
    EXPECT_EQ(a.covariances[size_t(25 + k)], before.covariances[size_t(k)]);
  }
  EXPECT_EQ(a.faces[16], (std::vector<int>{1, 0, 25, 26}));  // face 0 has 0 → 1
}

TEST(ExtrudeEdges, RefusesInteriorEdgesAndNonEdges) {
  const CovarianceMesh grid = make_sample("grid", 16);
  const MeshArrays before = arrays_of(grid);
  EXPECT_EQ(error_of([&] { extrude_edges(grid, {{0, 1}, {6, 7}}, Vec3(0, 0, 1)); }), "edge 6–7 is not on a boundary");
  EXPECT_EQ(error_of([&] { extrude_edges(grid, {{0, 6}}, Vec3(0, 0, 1)); }), "edge 0–6 is not in the mesh");
  EXPECT_EQ(error_of([&] { extrude_edges(grid, {{0, 99}}, Vec3(0, 0, 1)); }), "edge 0–99 is not in the mesh");
  EXPECT_EQ(error_of([&] { extrude_edges(grid, {{0, 1}}, Vec3(0, INFINITY, 1)); }), "offset (0, inf, 1) is not finite");
  expect_same(arrays_of(grid), before);
}

TEST(ExtrudeVertices, SelectedFacesAreExtrudedAndMovedByTheOffset) {
  const CovarianceMesh grid = make_sample("grid", 16);
  const MeshArrays before = arrays_of(grid);
  const Vec3 offset(0.1, 0.2, 0.3);
  const Modelled m = extrude_vertices(grid, {0, 1, 5, 6}, offset);
  EXPECT_EQ(int(m.mesh.n_vertices()), 29);
  EXPECT_EQ(int(m.mesh.n_faces()), 20);
  EXPECT_TRUE(shape_of(m.mesh).oriented);
  EXPECT_EQ(m.selection, (std::vector<int>{25, 26, 27, 28}));
  const MeshArrays a = arrays_of(m.mesh);
  const std::vector<int> originals = {0, 1, 5, 6};
  for (size_t k = 0; k < 4; ++k) EXPECT_EQ(a.means[25 + k], before.means[size_t(originals[k])] + offset);
}

// The editor's E in face mode: exactly the faces given, here a ring of eight quads around the centre
// one of a 3×3 grid (from its vertices the centre face would go with them): 16 side quads, the centre
// face left where it was; the same as extrude_vertices where the faces are all that the corners hold.
TEST(ExtrudeFacesBy, ExtrudesExactlyTheFacesGivenAndMovesThem) {
  const CovarianceMesh grid = make_sample("grid", 9);
  ASSERT_EQ(grid.n_faces(), 9u);
  const Vec3 offset(0.0, 0.0, 0.5);
  const Modelled ring = extrude_faces_by(grid, {0, 1, 2, 3, 5, 6, 7, 8}, offset);
  const Shape s = shape_of(ring.mesh);
  EXPECT_EQ(s.faces, 9 + 16);
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(s.euler(), shape_of(grid).euler());
  const MeshArrays before = arrays_of(grid), after = arrays_of(ring.mesh);
  EXPECT_EQ(after.faces[4], before.faces[4]) << "the centre face stays";
  for (const int v : after.faces[4]) EXPECT_EQ(after.means[size_t(v)], before.means[size_t(v)]);
  EXPECT_EQ(ring.selection.size(), 16u);
  for (const int v : ring.selection) {  // each where a vertex of the grid was, moved by the offset
    bool moved = false;
    for (const Vec3& p : before.means) moved = moved || after.means[size_t(v)] == p + offset;
    EXPECT_TRUE(moved) << "vertex " << v;
  }

  const Modelled one = extrude_faces_by(grid, {4}, offset);
  expect_same(arrays_of(one.mesh), arrays_of(extrude_vertices(grid, before.faces[4], offset).mesh));
  EXPECT_EQ(error_of([&] { extrude_faces_by(grid, {}, offset); }), "no faces are selected");
  EXPECT_NE(error_of([&] { extrude_faces_by(grid, {4}, Vec3(0, NAN, 0)); }), "");
}

TEST(ExtrudeVertices, WithoutFacesTheSelectedBoundaryEdgesAreExtruded) {
  const CovarianceMesh grid = make_sample("grid", 16);
  const Modelled m = extrude_vertices(grid, {2, 0, 1}, Vec3(0, -1, 0));
  EXPECT_EQ(int(m.mesh.n_vertices()), 28);
  EXPECT_EQ(int(m.mesh.n_faces()), 18);
  EXPECT_TRUE(shape_of(m.mesh).oriented);
  EXPECT_EQ(error_of([&] {
              extrude_vertices(grid, {6, 12}, Vec3(0, 0, 1));
            }),
            "select faces or boundary edges to extrude");
  EXPECT_EQ(error_of([&] { extrude_vertices(grid, {25}, Vec3(0, 0, 1)); }),
            "vertex 25 is not in the mesh (25 vertices)");
}

}  // namespace
}  // namespace gps
