// Selecting with the pointer without a window (ui/editing/pointer_selection.h), on the framed cube: a
// face clicked in face mode, a box that takes only what the camera sees unless X-ray, Ctrl+click's
// shortest path, an Alt+click loop on a grid, nothing picked where something is hidden, and the
// status bar's summary.
#include "ui/editing/pointer_selection.h"

#include <gtest/gtest.h>

#include "core/modelling/samples.h"
#include "tests/support/test_meshes.h"
#include "tests/support/view_pixels.h"
#include "view/visible_vertices.h"

namespace gps {
namespace {

using test::pixel_of;

const std::vector<char> kNothingHidden;

PointerScene scene_of(const Viewport& view, const CovarianceMesh& mesh, SelectMode mode,
                      const std::vector<char>& hidden_faces = kNothingHidden) {
  return {view, mesh, mode, kNothingHidden, kNothingHidden, hidden_faces};
}

// The centre of `face` on screen.
glm::vec2 face_centre(const Viewport& view, const CovarianceMesh& mesh, int face) {
  Vec3 c = Vec3::Zero();
  for (const int v : mesh.face(size_t(face))) c += mesh.mean(size_t(v)) / double(mesh.face(size_t(face)).size());
  return pixel_of(view, c);
}

// A face of the cube that faces the camera.
int front_face(const Viewport& view, const CovarianceMesh& mesh) {
  const std::vector<char> visible = visible_vertices(view, mesh);
  for (size_t f = 0; f < mesh.n_faces(); ++f) {
    bool all = true;
    for (const int v : mesh.face(f)) all = all && visible[size_t(v)];
    if (all) return int(f);
  }
  return -1;
}

TEST(PointerSelection, AFaceClickedInFaceModeIsHeldAndAHiddenOneIsNot) {
  const CovarianceMesh cube = make_sample("cube");
  const Viewport view = test::framed_view(cube);
  const int face = front_face(view, cube);
  ASSERT_GE(face, 0);
  Selection selection;
  click_select(selection, scene_of(view, cube, SelectMode::face), face_centre(view, cube, face), -1, false);
  EXPECT_EQ(selection.faces(cube), std::vector<int>{face});
  EXPECT_EQ(selection_summary(selection, cube, SelectMode::face, false), "4 selected, face mode: 1 face");

  std::vector<char> hidden(cube.n_faces(), 0);
  hidden[size_t(face)] = 1;
  Selection none;
  click_select(none, scene_of(view, cube, SelectMode::face, hidden), face_centre(view, cube, face), -1, false);
  for (const int f : none.faces(cube)) EXPECT_NE(f, face);
}

TEST(PointerSelection, ABoxTakesWhatTheCameraSeesAndAllWithXRay) {
  const CovarianceMesh cube = make_sample("cube");
  const Viewport view = test::framed_view(cube);
  const glm::vec2 a(0.0f), b(float(view.width), float(view.height));
  const HiddenElements nothing;
  Selection seen, all;
  box_select(seen, scene_of(view, cube, SelectMode::vertex), nothing, a, b, false, false, false);
  box_select(all, scene_of(view, cube, SelectMode::vertex), nothing, a, b, false, false, true);
  EXPECT_EQ(seen.vertices().size(), 7u);  // the corner at the back is not seen
  EXPECT_EQ(all.vertices().size(), 8u);
  EXPECT_EQ(selection_summary(all, cube, SelectMode::vertex, true), "8 selected, vertex mode, X-ray");
  box_select(all, scene_of(view, cube, SelectMode::vertex), nothing, a, b, false, true, false);  // Ctrl: subtract
  EXPECT_EQ(all.vertices().size(), 1u);
}

// A click on the corner the cube hides, or on the middle of an edge at it, picks what is in front:
// never the hidden corner or edge, which X-ray picks.
TEST(PointerSelection, AClickPicksWhatTheCameraSeesAndAllWithXRay) {
  const CovarianceMesh cube = make_sample("cube");
  const Viewport view = test::framed_view(cube);
  const std::vector<char> visible = visible_vertices(view, cube);
  const int back = int(std::find(visible.begin(), visible.end(), 0) - visible.begin());
  ASSERT_LT(back, 8);
  PointerScene scene = scene_of(view, cube, SelectMode::vertex);
  const glm::vec2 at_back = pixel_of(view, cube.mean(size_t(back)));
  const std::vector<int> seen = vertices_under(scene, at_back);
  EXPECT_TRUE(std::find(seen.begin(), seen.end(), back) == seen.end());
  EXPECT_EQ(unpickable_vertices(scene)[size_t(back)], 1);
  scene.through = true;
  EXPECT_EQ(vertices_under(scene, at_back), std::vector<int>{back});
  EXPECT_EQ(unpickable_vertices(scene)[size_t(back)], 0);

  for (size_t e = 0; e < cube.n_edges(); ++e) {
    const auto [a, b] = cube.edge(e);
    if (a != back && b != back) continue;
    const glm::vec2 middle = pixel_of(view, 0.5 * (cube.mean(size_t(a)) + cube.mean(size_t(b))));
    PointerScene edges = scene_of(view, cube, SelectMode::edge);
    Selection clicked, through;
    click_select(clicked, edges, middle, -1, false);
    for (const EdgeEnds& picked : clicked.edges(cube)) EXPECT_NE(picked, (EdgeEnds{a, b})) << a << "-" << b;
    edges.through = true;
    click_select(through, edges, middle, -1, false);
    EXPECT_EQ(through.edges(cube), std::vector<EdgeEnds>{(EdgeEnds{a, b})}) << a << "-" << b;
  }
}

TEST(PointerSelection, CtrlClickAddsTheShortestPathAndAltClickTheLoop) {
  const CovarianceMesh grid = test::grid_mesh(4, 4, 0.3, true);
  const Viewport view = test::framed_view(grid);
  Selection selection;
  const PointerScene vertices = scene_of(view, grid, SelectMode::vertex);
  click_select(selection, vertices, pixel_of(view, grid.mean(0)), 0, false);
  const SelectionNote path = path_select(selection, vertices, pixel_of(view, grid.mean(24)), 24);
  EXPECT_EQ(path.text, "shortest path: 8 edges");
  EXPECT_FALSE(path.error);
  EXPECT_EQ(selection.vertices().size(), 9u);
  EXPECT_EQ(selection.active(), 24);

  // Alt+click beside the middle of edge 6-7 of the second row: the row's loop of 5 vertices.
  Selection loop;
  const glm::vec2 middle = pixel_of(view, 0.5 * (grid.mean(6) + grid.mean(7)));
  EXPECT_EQ(loop_select(loop, vertices, middle, false).text, "edge loop: 5 vertices");
  EXPECT_EQ(loop.vertices(), (std::vector<int>{5, 6, 7, 8, 9}));
  EXPECT_TRUE(loop_select(loop, vertices, glm::vec2(-100.0f), false).text.empty());  // no edge there
}

}  // namespace
}  // namespace gps
