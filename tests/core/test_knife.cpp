// The knife (core/modelling/knife.h): the cube's top cut across as Blender's knife cuts it, new
// vertices split_edge's, a path over two faces and through a point inside a face, a triangle mesh
// kept triangles, creases split, refusals that change nothing, and the op list's "knife".
#include "core/modelling/knife.h"

#include <gtest/gtest.h>

#include "core/modelling/delete_elements.h"
#include "core/modelling/edge_operations.h"
#include "core/modelling/operation_list.h"
#include "core/modelling/samples.h"
#include "tests/support/error_of.h"
#include "tests/support/mesh_checks.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

using test::error_of;
using test::shape_of;
using test::signed_volume;

// The faces of `a` holding every vertex of `vertices`.
int faces_holding(const MeshArrays& a, const std::vector<int>& vertices) {
  int n = 0;
  for (const auto& face : a.faces)
    n += std::all_of(vertices.begin(), vertices.end(),
                     [&](int v) { return std::find(face.begin(), face.end(), v) != face.end(); });
  return n;
}

// The cube's top face is 4–5–6–7 at z = 1; its edges 4–5 and 6–7 face each other across it.
TEST(Knife, AcrossTheCubeTopFromEdgeMiddleToEdgeMiddle) {
  const CovarianceMesh cube = test::with_random_covariances(make_sample("cube"), 5);
  const CovarianceMesh copy = cube;
  const Modelled r = knife(cube, {Vec3(0, -1, 1), Vec3(0, 1, 1)});
  const test::Shape s = shape_of(r.mesh);
  EXPECT_EQ(s.vertices, 10);
  EXPECT_EQ(s.faces, 7);
  EXPECT_EQ(s.boundary_edges, 0);
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(s.euler(), 2);
  EXPECT_EQ(r.selection, (std::vector<int>{8, 9}));
  EXPECT_EQ(r.summary, "cut 1 face along 2 points: 2 vertices, 1 face added");
  const MeshArrays a = arrays_of(r.mesh);
  // The new vertices are split_edge's at the middles of 4–5 and 6–7, bit for bit.
  const MeshArrays at_45 = arrays_of(split_edge(cube, 4, 5, 0.5).mesh),
                   at_67 = arrays_of(split_edge(cube, 6, 7, 0.5).mesh);
  EXPECT_EQ(a.means[8], at_45.means[8]);
  EXPECT_EQ(a.covariances[8], at_45.covariances[8]);
  EXPECT_EQ(a.means[9], at_67.means[8]);
  EXPECT_EQ(a.covariances[9], at_67.covariances[8]);
  // The top is two quads either side of the cut; the front and back faces each gained a corner.
  EXPECT_EQ(faces_holding(a, {8, 9}), 2);
  EXPECT_EQ(faces_holding(a, {4, 8, 9, 7}), 1);
  EXPECT_EQ(faces_holding(a, {8, 5, 6, 9}), 1);
  EXPECT_EQ(faces_holding(a, {0, 1, 5, 8, 4}), 1);
  EXPECT_EQ(faces_holding(a, {2, 3, 7, 9, 6}), 1);
  EXPECT_TRUE(test::same_mesh(cube, copy));
}

TEST(Knife, ThePlacesOfTheCutKeepTheVolume) {
  const CovarianceMesh cube = make_sample("cube");
  const Modelled r = knife(cube, {Vec3(0, -1, 1), Vec3(0, 1, 1)});
  EXPECT_NEAR(signed_volume(r.mesh), 8.0, 1e-12);
  const MeshArrays a = arrays_of(r.mesh);
  EXPECT_TRUE(a.means[8].isApprox(Vec3(0, -1, 1), 1e-14));
  EXPECT_TRUE(a.means[9].isApprox(Vec3(0, 1, 1), 1e-14));
}

// From the middle of the top's back edge 6–7 to the middle of the front face (y = −1): over the top,
// across edge 4–5 and down the front, the end inside the front face moved on to its bottom edge 0–1.
TEST(Knife, APathOverTwoFacesEndingInsideOne) {
  const CovarianceMesh cube = make_sample("cube");
  const Modelled r = knife(cube, {Vec3(0, 1, 1), Vec3(0, -1, 0)});
  const test::Shape s = shape_of(r.mesh);
  EXPECT_EQ(s.vertices, 11);
  EXPECT_EQ(s.faces, 8);
  EXPECT_EQ(s.boundary_edges, 0);
  EXPECT_TRUE(s.oriented);
  EXPECT_NEAR(signed_volume(r.mesh), 8.0, 1e-12);
  const MeshArrays a = arrays_of(r.mesh);
  EXPECT_TRUE(a.means[8].isApprox(Vec3(0, 1, 1), 1e-14));
  EXPECT_TRUE(a.means[9].isApprox(Vec3(0, -1, 1), 1e-14));
  EXPECT_TRUE(a.means[10].isApprox(Vec3(0, -1, -1), 1e-14));
  EXPECT_EQ(faces_holding(a, {8, 9}), 2);   // the top's halves
  EXPECT_EQ(faces_holding(a, {9, 10}), 2);  // the front's halves
  EXPECT_EQ(faces_holding(a, {8, 10}), 0);
  EXPECT_EQ(r.selection, (std::vector<int>{8, 9, 10}));
}

// A bend at a point inside the top: that point becomes a vertex of both pieces, with the blend of
// the face's corners by mean value coordinates, which reproduce the point itself where the corners'
// covariances are equal (linear precision).
TEST(Knife, APointInsideAFaceBecomesACornerOfBothPieces) {
  const CovarianceMesh cube = make_sample("cube");
  const Modelled r = knife(cube, {Vec3(-1, 0, 1), Vec3(0.2, 0.5, 1), Vec3(1, 0, 1)});
  const test::Shape s = shape_of(r.mesh);
  EXPECT_EQ(s.vertices, 11);
  EXPECT_EQ(s.faces, 7);
  EXPECT_EQ(s.boundary_edges, 0);
  EXPECT_TRUE(s.oriented);
  EXPECT_NEAR(signed_volume(r.mesh), 8.0, 1e-12);
  const MeshArrays a = arrays_of(r.mesh);
  EXPECT_TRUE(a.means[9].isApprox(Vec3(0.2, 0.5, 1), 1e-12));
  EXPECT_EQ(faces_holding(a, {8, 9, 10}), 2);
  EXPECT_EQ(faces_holding(a, {4, 5, 10, 9, 8}), 1);
  EXPECT_EQ(faces_holding(a, {10, 6, 7, 8, 9}), 1);
}

TEST(Knife, ACutEndingOnAVertexUsesIt) {
  const CovarianceMesh cube = make_sample("cube");
  // Corner 4 to the middle of 5–6: the top is cut into a triangle and a quad, one vertex added.
  const Modelled r = knife(cube, {Vec3(-1, -1, 1), Vec3(1, 0, 1)});
  EXPECT_EQ(shape_of(r.mesh).vertices, 9);
  EXPECT_EQ(shape_of(r.mesh).faces, 7);
  const MeshArrays a = arrays_of(r.mesh);
  EXPECT_EQ(faces_holding(a, {4, 5, 8}), 1);
  EXPECT_EQ(faces_holding(a, {4, 8, 6, 7}), 1);
  EXPECT_EQ(r.selection, (std::vector<int>{4, 8}));
}

TEST(Knife, ATriangleMeshStaysTriangles) {
  const CovarianceMesh ico = make_sample("icosphere", 80);
  const MeshArrays before = arrays_of(ico);
  // From inside face 0 to inside a face across the sphere's side: both ends moved to edges.
  Vec3 first = Vec3::Zero(), last = Vec3::Zero();
  for (int v : before.faces[0]) first += before.means[size_t(v)] / 3;
  int far = 0;
  for (int f = 0; f < before.n_faces(); ++f) {
    Vec3 c = Vec3::Zero();
    for (int v : before.faces[size_t(f)]) c += before.means[size_t(v)] / 3;
    if ((c - first).norm() < 1.2 && (c - first).norm() > (last - first).norm()) last = c, far = f;
  }
  ASSERT_NE(far, 0);
  const Modelled r = knife(ico, {first, last});
  const MeshArrays a = arrays_of(r.mesh);
  const test::Shape s = shape_of(a);
  EXPECT_GT(s.vertices, before.n_vertices() + 2);
  EXPECT_TRUE(all_triangles(a));
  EXPECT_EQ(s.boundary_edges, 0);
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(s.euler(), 2);
  EXPECT_EQ(s.faces, 2 * s.vertices - 4);
  // Every new vertex is on the cut, and the cut is a chain of edges from end to end.
  EXPECT_EQ(r.selection.size(), size_t(s.vertices - before.n_vertices()));
  EXPECT_GT(signed_volume(a), 0);
}

// A path that ends on its first point cuts a loop, as Blender's knife closes one: round the cube's
// side through its vertical edges (a ring of four new vertices, a loop cut's), round a corner through
// points inside three faces (the start inside one: its first chord and its last are one), and round
// an icosphere's vertex through the middles of its faces. It was refused.
TEST(Knife, APathBackToItsStartCutsALoop) {
  const CovarianceMesh cube = make_sample("cube");
  const auto closed_and_outward = [](const CovarianceMesh& m) {
    const test::Shape s = shape_of(arrays_of(m));
    EXPECT_EQ(s.boundary_edges, 0);
    EXPECT_TRUE(s.oriented);
    EXPECT_EQ(s.euler(), 2);
    EXPECT_GT(signed_volume(arrays_of(m)), 0);
  };
  const Modelled ring =
      knife(cube, {Vec3(-1, -1, 0.5), Vec3(1, -1, 0.5), Vec3(1, 1, 0.5), Vec3(-1, 1, 0.5), Vec3(-1, -1, 0.5)});
  EXPECT_EQ(ring.mesh.n_vertices(), 12u);
  EXPECT_EQ(ring.mesh.n_faces(), 10u);
  EXPECT_EQ(ring.selection, (std::vector<int>{8, 9, 10, 11}));
  for (const int v : ring.selection) EXPECT_NEAR(ring.mesh.mean(size_t(v)).z(), 0.5, 1e-12);
  closed_and_outward(ring.mesh);

  const Modelled corner = knife(cube, {Vec3(0.5, -1, 0.5), Vec3(1, -0.5, 0.5), Vec3(0.5, -0.5, 1), Vec3(0.5, -1, 0.5)});
  closed_and_outward(corner.mesh);
  EXPECT_EQ(corner.mesh.n_vertices(), 8u + 6u);  // three points inside faces, three crossings of edges
  EXPECT_EQ(corner.mesh.n_faces(), 6u + 3u);     // each of the three faces cut in two
  EXPECT_EQ(corner.selection.size(), 6u);

  const CovarianceMesh ico = make_sample("icosphere", 80);
  const MeshArrays before = arrays_of(ico);
  std::vector<Vec3> path;
  for (const auto& face : before.faces)
    if (std::find(face.begin(), face.end(), 0) != face.end()) {
      Vec3 c = Vec3::Zero();
      for (const int v : face) c += before.means[size_t(v)] / 3;
      path.push_back(c);
    }
  ASSERT_GE(path.size(), 5u);
  // In order round vertex 0: by angle about its normal.
  const Vec3 n = before.means[0].normalized(), u = n.unitOrthogonal(), w = n.cross(u);
  std::sort(path.begin(), path.end(), [&](const Vec3& a, const Vec3& b) {
    return std::atan2(a.dot(w), a.dot(u)) < std::atan2(b.dot(w), b.dot(u));
  });
  path.push_back(path.front());
  const Modelled round = knife(ico, path);
  EXPECT_TRUE(all_triangles(arrays_of(round.mesh)));
  closed_and_outward(round.mesh);
  EXPECT_EQ(round.selection.size(), 2 * (path.size() - 1));  // a point inside each face, a crossing of each edge
}

// From the pawn's side down over the rim of its base to a point inside a triangle of the base's fan:
// the end moves on across that triangle the way the cut came (inwards), though the segment itself
// points outwards there.
TEST(Knife, AnEndInsideAFaceMovesOnTheWayTheCutCame) {
  const CovarianceMesh pawn = make_sample("pawn");
  const Vec3 side(-0.23217042930202123, 0.19745612160652598, 0.3325029648892527), base(-0.328437, 0.0, 0.359893);
  const Modelled r = knife(pawn, {side, base});
  const test::Shape s = shape_of(r.mesh);
  EXPECT_EQ(s.boundary_edges, 0);
  EXPECT_TRUE(s.oriented);
  EXPECT_EQ(s.euler(), shape_of(pawn).euler());
  // One vertex on each of the 7 edges the cut crosses down the side and over the rim, and the last on
  // an edge of the base's fan from its centre, vertex 0.
  const MeshArrays a = arrays_of(r.mesh);
  EXPECT_EQ(a.n_vertices(), int(pawn.n_vertices()) + 8);
  EXPECT_EQ(r.selection.size(), 8u);
  EXPECT_GE(faces_holding(a, {0, r.selection.back()}), 1);
}

TEST(Knife, ACreasedEdgeCutCreasesBothHalves) {
  MeshArrays a = arrays_of(make_sample("cube"));
  a.sharpness.set_crease(4, 5, 2.5);
  const CovarianceMesh creased = build_mesh(a);
  const CovarianceMesh r = knife(creased, {Vec3(0, -1, 1), Vec3(0, 1, 1)}).mesh;
  EXPECT_EQ(r.sharpness.crease(4, 8), 2.5);
  EXPECT_EQ(r.sharpness.crease(8, 5), 2.5);
  EXPECT_EQ(r.sharpness.crease(4, 5), 0.0);
  EXPECT_EQ(r.sharpness.crease(8, 9), 0.0);
}

TEST(Knife, RefusalsNameThePointAndChangeNothing) {
  const CovarianceMesh cube = make_sample("cube");
  const CovarianceMesh copy = cube;
  EXPECT_EQ(error_of([&] { knife(cube, {Vec3(0, -1, 1), Vec3(0, 0, 2)}); }), "point 2 is not on the mesh");
  EXPECT_EQ(error_of([&] { knife(cube, {Vec3(0, 0, 0), Vec3(0, 1, 1)}); }), "point 1 is not on the mesh");
  EXPECT_EQ(error_of([&] { knife(cube, {Vec3(0, -1, 1)}); }), "the knife needs at least 2 points, got 1");
  EXPECT_EQ(error_of([&] { knife(cube, {Vec3(0, -1, 1), Vec3(0, -1, 1), Vec3(0, 1, 1)}); }), "point 2 is at point 1");
  // A path back to its start round one other point (a loop needs three).
  EXPECT_EQ(error_of([&] {
              knife(cube, {Vec3(0.5, -1, 0.5), Vec3(1, -0.5, 0.5), Vec3(0.5, -1, 0.5)});
            }),
            "point 3 closes the path on point 1 after one other point; a loop needs three points or more");
  EXPECT_EQ(error_of([&] {
              knife(cube, {Vec3(0, -1, 1), Vec3(0, NAN, 1)});
            }),
            "point 2 has a number that is not finite");
  // Along edge 4–5 from end to end: nothing to cut.
  EXPECT_EQ(error_of([&] {
              knife(cube, {Vec3(-1, -1, 1), Vec3(1, -1, 1)});
            }),
            "the cut runs along edges already there: no face is split");
  // Across the top, back along its side and across again, over the first cut.
  EXPECT_EQ(error_of([&] {
              knife(cube, {Vec3(-1, -0.5, 1), Vec3(1, 0.5, 1), Vec3(1, -0.5, 1), Vec3(-1, 0.5, 1)});
            }),
            "the cut crosses itself in face 1");
  // Crossing itself between points inside one face, where no edge is crossed twice: seen in the
  // face's plane, not in the pieces' corners.
  for (const std::vector<Vec3>& path :
       {std::vector<Vec3>{Vec3(-0.5, 0, 1), Vec3(0.5, 0, 1), Vec3(0, 0.5, 1), Vec3(0, -0.5, 1)},
        std::vector<Vec3>{Vec3(-0.5, -0.5, 1), Vec3(0.5, 0.5, 1), Vec3(0.5, -0.5, 1), Vec3(-0.5, 0.5, 1)}})
    EXPECT_EQ(error_of([&] { knife(cube, path); }), "the cut crosses itself in face 1");
  // A loop inside the top face that meets none of its edges: a hole, not a cut.
  EXPECT_EQ(error_of([&] {
              knife(cube, {Vec3(-0.5, -0.5, 1), Vec3(0.5, -0.5, 1), Vec3(0, 0.5, 1), Vec3(-0.5, -0.5, 1)});
            }),
            "the closed path lies inside face 1 and would cut a hole in it; a loop must cross the face's edges");
  EXPECT_TRUE(test::same_mesh(cube, copy));
}

TEST(Knife, LeavingAnOpenMeshAtItsBoundaryIsRefused) {
  // The cube without its top: from inside the front face towards the back's top edge, the cut across
  // the front runs up into the open top.
  const CovarianceMesh box = delete_faces(make_sample("cube"), {1}).mesh;
  const CovarianceMesh copy = box;
  EXPECT_EQ(error_of([&] {
              knife(box, {Vec3(0, -1, 0.5), Vec3(0.5, 1, 1)});
            }),
            "the cut from point 1 to point 2 leaves the mesh at its boundary");
  // Front to back straight through the box: the segment is the faces' normal, so no plane holds both.
  EXPECT_EQ(error_of([&] {
              knife(box, {Vec3(0, -1, 0.5), Vec3(0, 1, 0.5)});
            }),
            "the cut from point 1 to point 2 runs along the surface's normal");
  EXPECT_TRUE(test::same_mesh(box, copy));
}

TEST(Knife, TheOperationList) {
  const CovarianceMesh cube = make_sample("cube");
  const Modelled scripted =
      OperationList::parse(R"([{"op":"knife","points":[[0,-1,1],[0.2,0.5,1],[1,0,1]]}])", "ops.json").apply(cube);
  EXPECT_TRUE(test::same_mesh(scripted.mesh, knife(cube, {Vec3(0, -1, 1), Vec3(0.2, 0.5, 1), Vec3(1, 0, 1)}).mesh));
  EXPECT_EQ(scripted.selection, (std::vector<int>{8, 9, 10}));
  const auto parse_error = [](const std::string& text) {
    return error_of([&] { OperationList::parse(text, "ops.json"); });
  };
  EXPECT_EQ(parse_error(R"([{"op":"knife"}])"), "ops.json: ops[0] (knife): \"points\" is missing");
  EXPECT_EQ(parse_error(R"([{"op":"knife","points":[[0,0,1]]}])"),
            "ops.json: ops[0] (knife): \"points\" must be a list of at least 2 [x, y, z] points");
  EXPECT_EQ(parse_error(R"([{"op":"knife","points":[[0,0,1],[0,1]]}])"),
            "ops.json: ops[0] (knife): \"points\"[1] must be 3 numbers");
  EXPECT_EQ(parse_error(R"([{"op":"knife","points":[[0,0,1],[0,1,1]],"depth":1}])"),
            "ops.json: ops[0] (knife): unknown key 'depth'");
  EXPECT_EQ(error_of([&] {
              OperationList::parse(R"([{"op":"knife","points":[[0,-1,1],[0,1,3]]}])", "ops.json").apply(cube);
            }),
            "ops.json: ops[0] (knife): point 2 is not on the mesh");
}

}  // namespace
}  // namespace gps
