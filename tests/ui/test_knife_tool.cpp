// Where the knife's clicks land on the control mesh (ui/tools/knife_tool.h knife_point_under): on
// the cube seen from +x, +y, +z, a corner or edge middle within a few pixels, a point of the face under
// the pointer, never a corner hidden behind the faces in front, nothing off the mesh.
#include "ui/tools/knife_tool.h"

#include <gtest/gtest.h>

#include "core/modelling/samples.h"
#include "tests/support/view_pixels.h"

namespace gps {
namespace {

class KnifePoints : public ::testing::Test {
protected:
  // The pixel whose centre p projects to, moved by `offset`.
  glm::vec2 pixel_of(const Vec3& p, glm::vec2 offset = glm::vec2(0.0f)) const {
    return test::pixel_of(view_, p) + offset;
  }
  Vec3 mean(int v) const { return mesh_.mean(size_t(v)); }
  CovarianceMesh mesh_ = make_sample("cube");
  Viewport view_ = test::framed_view(mesh_);
};

TEST_F(KnifePoints, CornersAndEdgeMiddlesNearThePointerAreTakenExactly) {
  const auto corner = knife_point_under(mesh_, view_, pixel_of(mean(6), glm::vec2(3.0f, -2.0f)));
  ASSERT_TRUE(corner);
  EXPECT_EQ(*corner, mean(6));
  const Vec3 middle = (mean(6) + mean(7)) / 2;
  const auto snapped = knife_point_under(mesh_, view_, pixel_of(middle, glm::vec2(2.0f, 3.0f)));
  ASSERT_TRUE(snapped);
  EXPECT_EQ(*snapped, middle);
}

TEST_F(KnifePoints, APointInsideTheTopFaceLiesOnItUnderThePointer) {
  const Vec3 inside(0.3, -0.2, 1.0);
  const glm::vec2 pixel = pixel_of(inside);
  const auto p = knife_point_under(mesh_, view_, pixel);
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->z(), 1.0, 1e-9);
  EXPECT_LT(glm::length(pixel_of(*p) - pixel), 0.01f);
  // Near an edge but away from its middle and corners: the edge's point under the pointer.
  const Vec3 on_edge = mean(6) + 0.3 * (mean(7) - mean(6));
  const auto e = knife_point_under(mesh_, view_, pixel_of(on_edge, glm::vec2(0.0f, 2.0f)));
  ASSERT_TRUE(e);
  EXPECT_NEAR(e->y(), 1.0, 1e-9);
  EXPECT_NEAR(e->z(), 1.0, 1e-9);
}

TEST_F(KnifePoints, AHiddenCornerIsNotTakenAndOffTheMeshIsNothing) {
  // Corner 0 (−1, −1, −1) is behind the three faces the camera sees, yet projects inside them.
  const auto p = knife_point_under(mesh_, view_, pixel_of(mean(0)));
  ASSERT_TRUE(p);
  EXPECT_NE(*p, mean(0));
  const Vec3 eye = to_vec(view_.camera.eye_double());
  EXPECT_LT((*p - eye).norm(), (mean(0) - eye).norm() - 1.0);
  EXPECT_FALSE(knife_point_under(mesh_, view_, glm::vec2(2.0f, 2.0f)));
}

}  // namespace
}  // namespace gps
