// Picking edges and faces under the mouse (view/element_picking.h) on the cube.
#include "view/element_picking.h"

#include <gtest/gtest.h>

#include "core/modelling/samples.h"
#include "tests/support/view_pixels.h"
#include "view/picking.h"
#include "view/visible_vertices.h"

namespace gps {
namespace {

using test::pixel_of;

class ElementPicking : public ::testing::Test {
protected:
  CovarianceMesh mesh_ = make_sample("cube");
  Viewport view_ = test::framed_view(mesh_);
};

TEST_F(ElementPicking, AnEdgesMidpointPicksItAndTheFrontMostWins) {
  const std::vector<char> visible = visible_vertices(view_, mesh_);
  int picked = 0;
  for (size_t e = 0; e < mesh_.n_edges(); ++e) {
    const auto [a, b] = mesh_.edge(e);
    if (!visible[size_t(a)] || !visible[size_t(b)]) continue;  // edges of the hidden corner may lie behind others
    const glm::vec2 mid = pixel_of(view_, 0.5 * (mesh_.mean(size_t(a)) + mesh_.mean(size_t(b))));
    const auto edge = pick_edge(view_, mid + glm::vec2(2.0f, -1.0f), mesh_, 8.0f);
    ASSERT_TRUE(edge.has_value()) << a << "-" << b;
    EXPECT_EQ(*edge, (std::array<int, 2>{std::min(a, b), std::max(a, b)}));
    ++picked;
  }
  EXPECT_EQ(picked, 9);  // the edges not at the hidden corner
  EXPECT_FALSE(pick_edge(view_, glm::vec2(5.0f, 5.0f), mesh_, 8.0f).has_value());
}

TEST_F(ElementPicking, AFacesCentrePicksTheFrontFaceThere) {
  const Vec3 eye = to_vec(view_.camera.eye());
  int front_faces = 0;
  for (int f = 0; f < int(mesh_.n_faces()); ++f) {
    Vec3 centre = Vec3::Zero();
    for (const int v : mesh_.face(size_t(f))) centre += 0.25 * mesh_.mean(size_t(v));
    const bool front = centre.dot(eye - centre) > 0;  // the cube's face normals point from its centre
    const int picked = pick_face(view_, pixel_of(view_, centre), mesh_);
    if (front) {
      EXPECT_EQ(picked, f);
      ++front_faces;
    } else {
      EXPECT_NE(picked, f) << "a back face is behind a front one";
    }
  }
  EXPECT_EQ(front_faces, 3);
  EXPECT_EQ(pick_face(view_, glm::vec2(5.0f, 5.0f), mesh_), -1);
}

// Hidden elements are left out: a hidden front face lets the pick through to the face behind it; a
// hidden edge or vertex is never picked, the nearest shown one is.
TEST_F(ElementPicking, HiddenElementsAreNotPicked) {
  const Vec3 eye = to_vec(view_.camera.eye());
  for (int f = 0; f < int(mesh_.n_faces()); ++f) {
    Vec3 centre = Vec3::Zero();
    for (const int v : mesh_.face(size_t(f))) centre += 0.25 * mesh_.mean(size_t(v));
    if (centre.dot(eye - centre) <= 0) continue;
    std::vector<char> hidden(mesh_.n_faces(), 0);
    hidden[size_t(f)] = 1;
    const int behind = pick_face(view_, pixel_of(view_, centre), mesh_, &hidden);
    EXPECT_NE(behind, f);
    EXPECT_GE(behind, 0) << "the cube's back faces lie behind each front face's centre";
  }
  const auto [a, b] = mesh_.edge(0);
  const glm::vec2 mid = pixel_of(view_, 0.5 * (mesh_.mean(size_t(a)) + mesh_.mean(size_t(b))));
  std::vector<char> hidden_edges(mesh_.n_edges(), 0);
  hidden_edges[0] = 1;
  const auto edge = pick_edge(view_, mid, mesh_, 8.0f, &hidden_edges);
  EXPECT_TRUE(!edge || *edge != (std::array<int, 2>{std::min(a, b), std::max(a, b)}));
  std::vector<char> all_edges(mesh_.n_edges(), 1);
  EXPECT_FALSE(pick_edge(view_, mid, mesh_, 8.0f, &all_edges).has_value());

  const glm::vec2 at_vertex = pixel_of(view_, mesh_.mean(size_t(a)));
  const int shown = pick_vertex(view_.camera, view_.width, view_.height, at_vertex, mesh_, 8.0f);
  ASSERT_GE(shown, 0);
  std::vector<char> hidden_vertices(mesh_.n_vertices(), 0);
  hidden_vertices[size_t(shown)] = 1;
  EXPECT_NE(pick_vertex(view_.camera, view_.width, view_.height, at_vertex, mesh_, 8.0f, &hidden_vertices), shown);
}

}  // namespace
}  // namespace gps
