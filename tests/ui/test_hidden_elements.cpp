// Hide and reveal (H, Shift+H, Alt+H) on the cube sample: faces 0 {0,3,2,1} (z = −1), 1 {4,5,6,7},
// 2 {0,1,5,4}, 3 {2,3,7,6}, 4 {1,2,6,5}, 5 {0,4,7,3}; vertex 0 lies on faces 0, 2 and 5.
#include "ui/editing/hidden_elements.h"

#include <gtest/gtest.h>

#include "core/modelling/samples.h"

namespace gps {
namespace {

using V = std::vector<int>;
using E = std::vector<EdgeEnds>;

TEST(HiddenElements, HidingAFaceHidesOnlyItAndDeselectsIt) {
  const CovarianceMesh cube = make_sample("cube");
  Selection selection;
  selection.select({0, 1, 2, 3}, false);  // face 0
  HiddenElements hidden;
  EXPECT_EQ(hidden.hide(cube, selection, SelectMode::face, false), 1u);
  EXPECT_EQ(hidden.faces(), (V{0}));
  EXPECT_TRUE(hidden.vertices().empty());   // each corner keeps two shown faces
  EXPECT_TRUE(hidden.edges(cube).empty());  // each edge keeps a shown face
  EXPECT_TRUE(selection.empty());
  EXPECT_EQ(hidden.face_mask(6), (std::vector<char>{1, 0, 0, 0, 0, 0}));
}

TEST(HiddenElements, AVertexAndItsEdgesGoWithTheirLastFace) {
  const CovarianceMesh cube = make_sample("cube");
  Selection selection;
  HiddenElements hidden;
  selection.select({0, 1, 2, 3}, false);  // face 0
  hidden.hide(cube, selection, SelectMode::face, false);
  selection.select({0, 1, 4, 5}, false);  // face 2
  hidden.hide(cube, selection, SelectMode::face, false);
  EXPECT_TRUE(hidden.vertices().empty());
  EXPECT_EQ(hidden.edges(cube), (E{{0, 1}}));  // between two hidden faces
  selection.select({0, 3, 4, 7}, false);       // face 5: vertex 0's last face
  EXPECT_EQ(hidden.hide(cube, selection, SelectMode::face, false), 1u);
  EXPECT_EQ(hidden.faces(), (V{0, 2, 5}));
  EXPECT_EQ(hidden.vertices(), (V{0}));
  EXPECT_EQ(hidden.edges(cube), (E{{0, 1}, {0, 3}, {0, 4}}));
  EXPECT_TRUE(hidden.edge_hidden(cube, 4, 0));
  EXPECT_FALSE(hidden.edge_hidden(cube, 1, 2));
  const std::vector<char> edges = hidden.edge_mask(cube);
  EXPECT_EQ(std::count(edges.begin(), edges.end(), 1), 3);
}

TEST(HiddenElements, VertexModeHidesTheVertexAndTheFacesAroundIt) {
  const CovarianceMesh cube = make_sample("cube");
  Selection selection;
  selection.click(0, false);
  HiddenElements hidden;
  EXPECT_EQ(hidden.hide(cube, selection, SelectMode::vertex, false), 3u);
  EXPECT_EQ(hidden.faces(), (V{0, 2, 5}));
  EXPECT_EQ(hidden.vertices(), (V{0}));
  EXPECT_EQ(hidden.vertex_mask(8), (std::vector<char>{1, 0, 0, 0, 0, 0, 0, 0}));
  EXPECT_EQ(hidden.shown({3, 0, 6}), (V{3, 6}));
  EXPECT_TRUE(selection.empty());
}

TEST(HiddenElements, EdgeModeHidesTheFacesBesideTheEdge) {
  const CovarianceMesh cube = make_sample("cube");
  Selection selection;
  selection.click_edges(cube, {{0, 1}}, 0, false);
  HiddenElements hidden;
  EXPECT_EQ(hidden.hide(cube, selection, SelectMode::edge, false), 2u);
  EXPECT_EQ(hidden.faces(), (V{0, 2}));
  EXPECT_TRUE(hidden.vertices().empty());  // 0 and 1 keep a shown face each
  EXPECT_EQ(hidden.edges(cube), (E{{0, 1}}));
  EXPECT_TRUE(selection.empty());
}

TEST(HiddenElements, ShiftHHidesEverythingNotSelected) {
  const CovarianceMesh cube = make_sample("cube");
  Selection selection;
  selection.select({4, 5, 6, 7}, false);  // face 1
  HiddenElements hidden;
  EXPECT_EQ(hidden.hide(cube, selection, SelectMode::face, true), 5u);
  EXPECT_EQ(hidden.faces(), (V{0, 2, 3, 4, 5}));
  EXPECT_EQ(hidden.vertices(), (V{0, 1, 2, 3}));     // on hidden faces only
  EXPECT_EQ(selection.vertices(), (V{4, 5, 6, 7}));  // the selected face stays, selected

  Selection vertex;
  vertex.click(6, false);
  HiddenElements around;
  EXPECT_EQ(around.hide(cube, vertex, SelectMode::vertex, true), 6u);  // every face has another corner
  EXPECT_EQ(around.vertices(), (V{0, 1, 2, 3, 4, 5, 7}));
  EXPECT_EQ(vertex.vertices(), (V{6}));
}

TEST(HiddenElements, RevealShowsEverythingAndSelectsWhatWasHidden) {
  const CovarianceMesh cube = make_sample("cube");
  Selection selection;
  HiddenElements hidden;
  selection.select({0, 1, 2, 3}, false);
  hidden.hide(cube, selection, SelectMode::face, false);
  selection.select_faces(cube, {1}, false);  // face mode holds faces: {4, 5, 6, 7}
  EXPECT_EQ(hidden.reveal(cube, selection, SelectMode::face), 1u);
  EXPECT_TRUE(hidden.empty());
  EXPECT_EQ(selection.faces(cube), (V{0, 1}));  // the hidden face {0, 3, 2, 1} added
  EXPECT_EQ(selection.vertices(), (V{0, 1, 2, 3, 4, 5, 6, 7}));

  Selection edges;
  HiddenElements by_edge;
  edges.click_edges(cube, {{0, 1}}, 0, false);
  by_edge.hide(cube, edges, SelectMode::edge, false);
  edges.click_edges(cube, {{6, 7}}, 6, false);
  EXPECT_EQ(by_edge.reveal(cube, edges, SelectMode::edge), 2u);
  EXPECT_EQ(edges.edges(cube), (E{{0, 1}, {6, 7}}));
  EXPECT_EQ(by_edge.reveal(cube, edges, SelectMode::edge), 0u);  // nothing hidden: nothing changes
  EXPECT_EQ(edges.edges(cube), (E{{0, 1}, {6, 7}}));
}

TEST(HiddenElements, SelectAllThenDeselectHiddenLeavesTheHiddenOut) {
  const CovarianceMesh cube = make_sample("cube");
  Selection selection;
  selection.click(0, false);
  HiddenElements hidden;
  hidden.hide(cube, selection, SelectMode::vertex, false);
  selection.select_all(cube.n_vertices());
  hidden.deselect_hidden(cube, selection, SelectMode::vertex);
  EXPECT_EQ(selection.vertices(), (V{1, 2, 3, 4, 5, 6, 7}));
  // Edge mode: the hidden edges leave, the others stay.
  selection.select_all(cube.n_vertices());
  selection.hold_edges(cube);
  hidden.deselect_hidden(cube, selection, SelectMode::edge);
  EXPECT_EQ(selection.edges(cube).size(), 12u - 3u);
  for (const EdgeEnds& e : selection.edges(cube)) EXPECT_FALSE(hidden.edge_hidden(cube, e[0], e[1]));
}

// What is hidden stays through a change that keeps the faces (a crease); another topology is
// another mesh's indices.
TEST(HiddenElements, FitsOnlyTheFacesItWasHiddenIn) {
  CovarianceMesh cube = make_sample("cube");
  Selection selection;
  HiddenElements hidden;
  EXPECT_TRUE(hidden.fits(make_sample("cylinder")));  // nothing hidden
  selection.select({0, 1, 2, 3}, false);
  hidden.hide(cube, selection, SelectMode::face, false);
  cube.sharpness.creases.push_back({0, 1, 2.0});
  EXPECT_TRUE(hidden.fits(cube));
  EXPECT_FALSE(hidden.fits(make_sample("cylinder")));
  const CovarianceMesh wire = make_sample("wirecube");  // another mesh
  EXPECT_FALSE(hidden.fits(wire));
  hidden.clear();
  EXPECT_TRUE(hidden.empty());
  EXPECT_TRUE(hidden.fits(wire));
}

}  // namespace
}  // namespace gps
