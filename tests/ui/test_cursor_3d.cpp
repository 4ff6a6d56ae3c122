// The 3D cursor (ui/editing/cursor_3d.h): placed where it is told, and off the surface kept at its depth
// along the pointer's ray, as Blender keeps it.
#include "ui/editing/cursor_3d.h"

#include <gtest/gtest.h>

#include "core/modelling/samples.h"
#include "tests/support/view_pixels.h"

namespace gps {
namespace {

TEST(Cursor3D, IsPlacedWhereToldAndSaysWhere) {
  Cursor3D cursor;
  EXPECT_FALSE(cursor.placed);
  EXPECT_EQ(cursor.place(Vec3(1.5, -2, 0.25), "at the selection's centre"),
            "3D cursor at the selection's centre (1.5, -2, 0.25)");
  EXPECT_TRUE(cursor.placed);
  EXPECT_EQ(cursor.point, Vec3(1.5, -2, 0.25));
}

TEST(Cursor3D, OffTheSurfaceItKeepsItsDepthUnderThePointer) {
  const Viewport view = test::framed_view(make_sample("cube"));
  Cursor3D cursor;
  cursor.place(Vec3(0.3, -0.2, 0.4), "at");
  const Vec3 eye = to_vec(view.camera.eye_double());
  const Vec3 facing = (to_vec(view.camera.target) - eye).normalized();
  for (const glm::vec2 pixel : {test::pixel_of(view, cursor.point), glm::vec2(5.0f, 7.0f),
                                glm::vec2(float(view.width) - 3.0f, float(view.height) / 2.0f)}) {
    const std::optional<Vec3> at = cursor.at_its_depth(view, pixel);
    ASSERT_TRUE(at);
    EXPECT_NEAR((*at - cursor.point).dot(facing), 0.0, 1e-9);  // on the plane through it facing the view
    const Ray ray = pixel_ray(view.camera, view.width, view.height, pixel);
    EXPECT_LT((*at - to_vec(ray.origin)).cross(to_vec(ray.direction)).norm(), 1e-9);  // under the pointer
  }
  // Under the cursor's own pixel: the cursor itself.
  EXPECT_LT((*cursor.at_its_depth(view, test::pixel_of(view, cursor.point)) - cursor.point).norm(), 1e-3);
}

}  // namespace
}  // namespace gps
