#include "ui/editing/selection.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/modelling/mesh_queries.h"
#include "core/modelling/samples.h"
#include "tests/support/test_meshes.h"
#include "view/picking.h"

namespace gps {
namespace {

TEST(Selection, ClickShiftClickAllNone) {
  Selection s;
  EXPECT_EQ(s.active(), -1);
  s.click(4, false);
  EXPECT_EQ(s.vertices(), std::vector<int>{4});
  s.click(2, true);
  s.click(7, true);
  EXPECT_EQ(s.vertices(), (std::vector<int>{2, 4, 7}));
  EXPECT_EQ(s.active(), 7);
  s.click(4, true);  // shift-click on a selected vertex removes it
  EXPECT_EQ(s.vertices(), (std::vector<int>{2, 7}));
  EXPECT_EQ(s.active(), 2);  // the last clicked is gone: the first
  s.click(-1, true);         // shift-click on nothing keeps the selection
  EXPECT_EQ(s.vertices().size(), 2u);
  s.click(5, false);  // a plain click replaces it
  EXPECT_EQ(s.vertices(), std::vector<int>{5});
  s.click(-1, false);  // a plain click on nothing clears it
  EXPECT_TRUE(s.empty());
  s.select_all(4);
  EXPECT_EQ(s.vertices(), (std::vector<int>{0, 1, 2, 3}));
  s.select({1, 0}, false);
  EXPECT_EQ(s.vertices(), (std::vector<int>{0, 1}));
  s.select({3, 1, 3}, true);
  EXPECT_EQ(s.vertices(), (std::vector<int>{0, 1, 3}));
  s.select({2}, false);
  EXPECT_EQ(s.vertices(), std::vector<int>{2});
  s.clear();
  EXPECT_TRUE(s.empty());
}

TEST(Selection, AGroupClickSelectsAnEdgeOrFaceAndShiftTogglesIt) {
  Selection s;
  s.click_group({3, 1}, 3, false);
  EXPECT_EQ(s.vertices(), (std::vector<int>{1, 3}));
  EXPECT_EQ(s.active(), 3);
  s.click_group({5, 6, 2, 1}, 6, true);  // not all selected: added
  EXPECT_EQ(s.vertices(), (std::vector<int>{1, 2, 3, 5, 6}));
  EXPECT_EQ(s.active(), 6);
  s.click_group({6, 5, 2, 1}, 5, true);  // all selected: removed, the vertex only the edge had stays
  EXPECT_EQ(s.vertices(), std::vector<int>{3});
  s.click_group({}, -1, true);  // shift on nothing keeps it
  EXPECT_EQ(s.vertices(), std::vector<int>{3});
  s.click_group({0, 4}, 0, false);
  EXPECT_EQ(s.vertices(), (std::vector<int>{0, 4}));
  s.click_group({}, -1, false);  // a plain click on nothing clears it
  EXPECT_TRUE(s.empty());
}

TEST(Selection, DeselectAndInvert) {
  Selection s;
  s.select({0, 2, 3, 5, 9}, false);
  s.deselect({9, 3, 7});
  EXPECT_EQ(s.vertices(), (std::vector<int>{0, 2, 5}));
  s.invert(7);
  EXPECT_EQ(s.vertices(), (std::vector<int>{1, 3, 4, 6}));
  s.invert(7);
  EXPECT_EQ(s.vertices(), (std::vector<int>{0, 2, 5}));
  s.clear();
  s.invert(3);
  EXPECT_EQ(s.vertices(), (std::vector<int>{0, 1, 2}));
  s.invert(3);
  EXPECT_TRUE(s.empty());
  EXPECT_EQ(select_mode_name(SelectMode::edge), "edge");
}

TEST(Selection, BoxSelectsExactlyTheVerticesProjectedInside) {
  const CovarianceMesh mesh = make_sample("grid", 256);
  const Camera camera = frame_mesh(mesh, 20.0f, 50.0f);
  const int w = 640, h = 480;
  const glm::vec2 a(150.0f, 120.0f), b(420.0f, 330.0f);
  const std::vector<int> inside = vertices_in_box(camera, w, h, b, a, mesh);  // corners in any order
  ASSERT_FALSE(inside.empty());
  for (size_t i = 0; i < mesh.n_vertices(); ++i) {
    const Vec3 m = mesh.mean(i);
    const auto p = project_to_pixel(camera, w, h, glm::vec3(float(m.x()), float(m.y()), float(m.z())));
    const bool in = p && p->x >= a.x && p->x <= b.x + 1 && p->y >= a.y && p->y <= b.y + 1;
    EXPECT_EQ(in, std::find(inside.begin(), inside.end(), int(i)) != inside.end()) << "vertex " << i;
  }
}

// Edge mode on a 4 × 4 grid (vertex j·5 + i): two parallel edges of one quad, {6, 7} and {11, 12},
// select those two edges only, not the quad's sides {6, 11} and {7, 12} that join their ends.
using Edges = std::vector<EdgeEnds>;

TEST(Selection, EdgeModeSelectsEdgesNotTheEdgesBetweenTheirEnds) {
  const CovarianceMesh grid = test::grid_mesh(4, 4);
  Selection s;
  s.click_edges(grid, {{7, 6}}, 7, false);
  s.click_edges(grid, {{12, 11}}, 12, true);  // shift-click adds
  EXPECT_TRUE(s.holds_edges());
  EXPECT_EQ(s.edges(grid), (Edges{{6, 7}, {11, 12}}));
  EXPECT_EQ(s.vertices(), (std::vector<int>{6, 7, 11, 12}));  // their ends, for G / S / R
  EXPECT_EQ(edges_within(grid, s.vertices()).size(), 4u);     // what the ends alone would select
  EXPECT_EQ(s.active(), 12);
  s.click_edges(grid, {{6, 7}}, 6, true);  // shift-click on a selected edge removes it
  EXPECT_EQ(s.edges(grid), (Edges{{11, 12}}));
  EXPECT_EQ(s.vertices(), (std::vector<int>{11, 12}));
  s.click_edges(grid, {}, -1, true);  // shift-click on nothing keeps the selection
  EXPECT_EQ(s.edges(grid), (Edges{{11, 12}}));
  s.click_edges(grid, {{0, 1}}, 0, false);  // a plain click replaces it
  EXPECT_EQ(s.edges(grid), (Edges{{0, 1}}));
  s.click_edges(grid, {}, -1, false);  // a plain click on nothing clears it
  EXPECT_TRUE(s.empty());
  EXPECT_TRUE(s.edges(grid).empty());
}

TEST(Selection, EdgeLoopsTogglesAsAGroup) {
  const CovarianceMesh grid = test::grid_mesh(4, 4);
  Selection s;
  const Edges row = edge_loop_edges(grid, 11, 12);  // the row 10 … 14
  s.click_edges(grid, row, 11, false);
  s.click_edges(grid, edge_loop_edges(grid, 16, 17), 16, true);  // and the row above
  EXPECT_EQ(s.edges(grid).size(), 8u);                           // not the 5 edges between the rows
  EXPECT_EQ(s.vertices().size(), 10u);
  s.click_edges(grid, row, 11, true);  // all of it selected: shift removes it
  EXPECT_EQ(s.edges(grid), edge_loop_edges(grid, 16, 17));
  s.click_edges(grid, {{10, 11}, {16, 17}}, 10, true);  // partly selected: shift adds the rest
  EXPECT_EQ(s.edges(grid).size(), 5u);
}

TEST(Selection, EdgeBoxesAndInvert) {
  const CovarianceMesh grid = test::grid_mesh(4, 4);  // 40 edges
  Selection s;
  s.select_edges(grid, {{6, 7}, {11, 12}}, false);
  s.select_edges(grid, {{0, 1}}, true);  // additive
  EXPECT_EQ(s.edges(grid), (Edges{{0, 1}, {6, 7}, {11, 12}}));
  s.select_edges(grid, {{1, 2}}, false);  // replacing
  EXPECT_EQ(s.edges(grid), (Edges{{1, 2}}));
  s.select_edges(grid, {{6, 7}, {11, 12}}, true);
  s.deselect_edges(grid, {{7, 6}, {3, 4}});  // one selected, one not
  EXPECT_EQ(s.edges(grid), (Edges{{1, 2}, {11, 12}}));
  s.invert_edges(grid);
  const Edges inverted = s.edges(grid);
  EXPECT_EQ(inverted.size(), 38u);
  EXPECT_FALSE(std::binary_search(inverted.begin(), inverted.end(), EdgeEnds{1, 2}));
  EXPECT_FALSE(std::binary_search(inverted.begin(), inverted.end(), EdgeEnds{11, 12}));
  EXPECT_EQ(s.vertices().size(), 25u);  // every vertex is an end of an edge left
  s.invert_edges(grid);
  EXPECT_EQ(s.edges(grid), (Edges{{1, 2}, {11, 12}}));
}

// Switching modes as Blender does: vertex → edge holds the edges with both ends selected (a vertex
// on none is let go); edge → vertex keeps the ends, whose edges are then all those between them.
TEST(Selection, ModeSwitchesConvertAsBlenderDoes) {
  const CovarianceMesh grid = test::grid_mesh(4, 4);
  Selection s;
  s.select({0, 6, 7, 11}, false);
  EXPECT_FALSE(s.holds_edges());
  EXPECT_EQ(s.edges(grid), (Edges{{6, 7}, {6, 11}}));
  s.hold_edges(grid);  // into edge mode
  EXPECT_TRUE(s.holds_edges());
  EXPECT_EQ(s.edges(grid), (Edges{{6, 7}, {6, 11}}));
  EXPECT_EQ(s.vertices(), (std::vector<int>{6, 7, 11}));  // vertex 0 had no selected edge
  s.click_edges(grid, {{6, 7}}, 6, false);
  s.click_edges(grid, {{11, 12}}, 11, true);
  s.hold_edges(grid);  // already edges: nothing changes
  EXPECT_EQ(s.edges(grid), (Edges{{6, 7}, {11, 12}}));
  s.release_edges();  // out of edge mode
  EXPECT_FALSE(s.holds_edges());
  EXPECT_EQ(s.vertices(), (std::vector<int>{6, 7, 11, 12}));
  EXPECT_EQ(s.edges(grid), (Edges{{6, 7}, {6, 11}, {7, 12}, {11, 12}}));
  // A vertex selection (an operation's result, select all) lets the edges go too.
  s.select_edges(grid, {{6, 7}}, false);
  s.select_all(grid.n_vertices());
  EXPECT_FALSE(s.holds_edges());
  EXPECT_EQ(s.edges(grid).size(), 40u);
}

// Held edges name vertices of the mesh they were picked on; on another mesh only those that are
// still its edges count.
// What the undo history keeps gives back the held edges, not every edge between their ends; a record
// of vertices alone selects vertices.
TEST(Selection, ARecordRestoresTheEdgesItHeld) {
  const CovarianceMesh grid = test::grid_mesh(4, 4);
  Selection s;
  s.select_edges(grid, {{6, 7}, {11, 12}}, false);
  const SelectionRecord record = s.record();
  EXPECT_TRUE(record.holds_edges);
  s.select({6, 7, 11, 12}, false);  // the ends alone: the quad's four sides
  EXPECT_EQ(s.edges(grid).size(), 4u);
  s.restore(record);
  EXPECT_TRUE(s.holds_edges());
  EXPECT_EQ(s.edges(grid), (Edges{{6, 7}, {11, 12}}));
  EXPECT_EQ(s.vertices(), (std::vector<int>{6, 7, 11, 12}));
  s.restore({{1, 2}});
  EXPECT_FALSE(s.holds_edges());
  EXPECT_EQ(s.vertices(), (std::vector<int>{1, 2}));
}

TEST(Selection, HeldEdgesNotInTheMeshAreLeftOut) {
  const CovarianceMesh grid = test::grid_mesh(4, 4);
  const CovarianceMesh cube = make_sample("cube");  // 8 vertices; 0–1 an edge, 0–5 a face's diagonal
  Selection s;
  s.select_edges(grid, {{0, 1}, {0, 5}, {5, 10}, {23, 24}}, false);
  EXPECT_EQ(s.edges(cube), (Edges{{0, 1}}));
}

}  // namespace
}  // namespace gps

namespace gps {
namespace {

// A 3×3 grid of quads: face f = 3j + i has corners (j, i), (j, i + 1), (j + 1, i + 1), (j + 1, i) of a
// 4×4 grid of vertices; the ring is every face but the centre one, 4.
const std::vector<int> kRing{0, 1, 2, 3, 5, 6, 7, 8};

// In face mode the selection holds faces: a ring of eight faces around the centre one has every
// vertex as a corner, but the centre face is not selected with them (as it is from vertices).
TEST(Selection, AHeldRingOfFacesLeavesOutTheFaceInside) {
  const CovarianceMesh grid = test::grid_mesh(3, 3);
  Selection s;
  s.click_faces(grid, {0}, 0, false);
  for (size_t k = 1; k < kRing.size(); ++k) s.click_faces(grid, {kRing[k]}, 0, true);
  EXPECT_TRUE(s.holds_faces());
  EXPECT_EQ(s.faces(grid), kRing);
  EXPECT_EQ(s.vertices().size(), 16u);
  EXPECT_EQ(faces_within(grid, s.vertices()).size(), 9u) << "from vertices, the centre face is taken too";
  s.click_faces(grid, {5}, 0, true);  // toggled off
  EXPECT_EQ(s.faces(grid), (std::vector<int>{0, 1, 2, 3, 6, 7, 8}));
  s.invert_faces(grid);
  EXPECT_EQ(s.faces(grid), (std::vector<int>{4, 5}));
  EXPECT_EQ(s.vertices(), (std::vector<int>{5, 6, 7, 9, 10, 11}));
  s.deselect_faces(grid, {4});
  EXPECT_EQ(s.faces(grid), std::vector<int>{5});
  s.select_faces(grid, {0, 8}, true);
  EXPECT_EQ(s.faces(grid), (std::vector<int>{0, 5, 8}));
  s.click_faces(grid, {}, -1, false);  // a plain click on nothing clears it
  EXPECT_TRUE(s.empty());
}

// Into face mode as Blender converts (the faces whose corners are all selected, and only their
// corners); out of it the corners stay; a vertex selection lets the faces go; the undo record gives
// the held faces back.
TEST(Selection, FaceModeConvertsAndARecordRestoresTheFaces) {
  const CovarianceMesh grid = test::grid_mesh(3, 3);
  Selection s;
  s.select({0, 1, 4, 5, 15}, false);
  s.hold_faces(grid);
  EXPECT_EQ(s.faces(grid), std::vector<int>{0});
  EXPECT_EQ(s.vertices(), (std::vector<int>{0, 1, 4, 5}));  // vertex 15 is on no selected face
  s.select_faces(grid, kRing, false);
  const SelectionRecord record = s.record();
  EXPECT_TRUE(record.holds_faces);
  s.release_faces();
  EXPECT_EQ(s.faces(grid).size(), 9u);
  s.restore(record);
  EXPECT_TRUE(s.holds_faces());
  EXPECT_EQ(s.faces(grid), kRing);
  s.hold_edges(grid);  // into edge mode: the faces go, their edges (and those among their corners) stay
  EXPECT_FALSE(s.holds_faces());
  EXPECT_EQ(s.edges(grid).size(), 24u);
  s.select_faces(grid, {4}, false);
  s.select_all(grid.n_vertices());
  EXPECT_FALSE(s.holds_faces());
  EXPECT_EQ(s.faces(grid).size(), 9u);
  s.hold_for(SelectMode::face, grid);  // as the face mode holds them
  EXPECT_TRUE(s.holds_faces());
  s.select_faces(grid, {4}, false);
  s.hold_for(SelectMode::vertex, grid);  // back to vertex mode: the corners stay
  EXPECT_FALSE(s.holds_faces());
  EXPECT_EQ(s.vertices(), (std::vector<int>{5, 6, 9, 10}));
}

// Held faces are known by their corners: on another mesh only those that are still its faces count,
// whatever their index there.
TEST(Selection, HeldFacesAreFoundByTheirCorners) {
  const CovarianceMesh grid = test::grid_mesh(3, 3);
  Selection s;
  s.select_faces(grid, {0, 4}, false);
  std::vector<std::vector<int>> faces;
  for (size_t f = 0; f < grid.n_faces(); ++f)
    faces.insert(faces.begin(), std::vector<int>(grid.face(f).begin(), grid.face(f).end()));  // in reverse order
  faces.erase(faces.begin());  // face 8 gone
  std::vector<Vec3> means;
  for (size_t v = 0; v < grid.n_vertices(); ++v) means.push_back(grid.mean(v));
  const CovarianceMesh reordered = make_covariance_mesh(means, grid.covariances, faces, "reordered");
  EXPECT_EQ(s.faces(reordered), (std::vector<int>{3, 7}));  // faces 4 and 0, now 7 − 4 and 7 − 0
  // On the cube, grid face 0's corners {0, 1, 4, 5} are those of its face 2; face 4's are not its vertices.
  const CovarianceMesh cube = make_sample("cube");
  EXPECT_EQ(s.faces(cube), std::vector<int>{2});
}

// The active face, where Ctrl+click's path of faces starts: the face last clicked alone, while it is
// held; a loop of faces or a vertex selection leaves none.
TEST(Selection, AFaceClickedAloneIsTheActiveFace) {
  const CovarianceMesh grid = test::grid_mesh(3, 3);
  Selection s;
  EXPECT_EQ(s.active_face(grid), -1);
  s.click_faces(grid, {4}, 5, false);
  EXPECT_EQ(s.active_face(grid), 4);
  s.click_faces(grid, {7}, 9, true);
  EXPECT_EQ(s.active_face(grid), 7);
  s.click_faces(grid, {0, 1, 2}, 0, true);  // a loop: the active face stays
  EXPECT_EQ(s.active_face(grid), 7);
  s.set_active_face(grid, 8);  // not held: nothing changes
  EXPECT_EQ(s.active_face(grid), 7);
  s.set_active_face(grid, 1);
  EXPECT_EQ(s.active_face(grid), 1);
  s.deselect_faces(grid, {1});
  EXPECT_EQ(s.active_face(grid), -1);
  s.click_faces(grid, {4}, 5, false);
  s.release_faces();
  EXPECT_EQ(s.active_face(grid), -1);
}

}  // namespace
}  // namespace gps
