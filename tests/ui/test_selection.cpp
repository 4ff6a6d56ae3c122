#include "ui/editing/selection.h"

#include <gtest/gtest.h>

#include "core/modelling/samples.h"
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

}  // namespace
}  // namespace gps
