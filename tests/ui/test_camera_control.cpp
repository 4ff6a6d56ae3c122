#include "ui/input/camera_control.h"

#include <gtest/gtest.h>

#include "core/modelling/samples.h"
#include "view/picking.h"

namespace gps {
namespace {

glm::vec2 pixel_of(const Camera& c, int w, int h, glm::dvec3 p) {
  const auto q = project_to_pixel(c, w, h, Vec3(p.x, p.y, p.z));
  EXPECT_TRUE(q.has_value());
  return glm::vec2(*q);
}

// Straight down or up the up axis (pitch ±90°) at a target far from the origin, the view keeps its
// sideways axis: the target maps to the middle of the view, at its distance straight ahead.
TEST(CameraView, StraightAlongTheUpAxisAtAFarTargetIsAView) {
  for (const float pitch : {90.0f, -90.0f})
    for (const double far : {0.0, 10.0, 1e7}) {
      Camera camera;
      camera.target = glm::dvec3(far, far, -far);
      camera.yaw_degrees = 45.0f;
      camera.pitch_degrees = pitch;
      camera.distance = 3.0f;
      const glm::dmat4 view = camera.view_double();
      const glm::dvec4 target = view * glm::dvec4(camera.target, 1.0);
      EXPECT_NEAR(target.x, 0.0, 1e-9 * std::max(1.0, far)) << pitch << " " << far;
      EXPECT_NEAR(target.y, 0.0, 1e-9 * std::max(1.0, far)) << pitch << " " << far;
      EXPECT_NEAR(target.z, -3.0, 1e-9 * std::max(1.0, far)) << pitch << " " << far;
      const glm::dvec4 above = view * glm::dvec4(camera.target + glm::dvec3(0, 1, 0), 1.0);
      EXPECT_NEAR(above.z, pitch > 0 ? -2.0 : -4.0, 1e-6) << pitch << " " << far;
    }
}

TEST(CameraControl, ZoomKeepsTheAnchorUnderTheCursor) {
  Camera camera = frame_box(Vec3(-1, -1, -1), Vec3(1, 1, 1));
  const glm::dvec3 anchor(0.4, 0.3, -0.2);
  const glm::vec2 cursor = pixel_of(camera, 800, 600, anchor);
  const float before = camera.distance;
  zoom_to_cursor(camera, 3.0f, 800, 600, cursor, anchor);
  EXPECT_NEAR(camera.distance, before * std::pow(0.85f, 3.0f), 1e-4f * before);
  EXPECT_LT(glm::length(pixel_of(camera, 800, 600, anchor) - cursor), 0.01f);
  zoom_to_cursor(camera, -5.0f, 800, 600, cursor, anchor);
  EXPECT_LT(glm::length(pixel_of(camera, 800, 600, anchor) - cursor), 0.01f);
  // Without a surface point the anchor is the cursor's point at the target's depth.
  Camera plain = frame_box(Vec3(-1, -1, -1), Vec3(1, 1, 1));
  const glm::vec2 corner(100.0f, 80.0f);
  const Ray ray = pixel_ray(plain, 800, 600, corner);
  const glm::dvec3 forward = glm::normalize(plain.target - plain.eye_double());
  const glm::dvec3 point = ray.origin + ray.direction * (double(plain.distance) / glm::dot(ray.direction, forward));
  zoom_to_cursor(plain, 2.0f, 800, 600, corner, std::nullopt);
  EXPECT_LT(glm::length(pixel_of(plain, 800, 600, point) - (corner + glm::vec2(0.5f))), 0.05f);
}

TEST(CameraControl, PanMovesThePointAtTheTargetDepthWithTheMouse) {
  Camera camera = frame_box(Vec3(-1, -1, -1), Vec3(1, 1, 1), 40.0f, 30.0f);
  const glm::dvec3 target = camera.target;
  const glm::vec2 before = pixel_of(camera, 640, 480, target);
  pan(camera, glm::vec2(35.0f, -20.0f), 480);
  EXPECT_LT(glm::length(pixel_of(camera, 640, 480, target) - (before + glm::vec2(35.0f, -20.0f))), 0.05f);
}

TEST(CameraControl, OrbitTurnsAroundTheTargetAndClampsPitch) {
  Camera camera;
  const glm::dvec3 target = camera.target;
  orbit(camera, glm::vec2(50.0f, 0.0f));
  EXPECT_NEAR(camera.yaw_degrees, 30.0f - 20.0f, 1e-4f);
  EXPECT_EQ(camera.target, target);
  orbit(camera, glm::vec2(0.0f, 10000.0f));
  EXPECT_EQ(camera.pitch_degrees, 89.0f);
  orbit(camera, glm::vec2(0.0f, -10000.0f));
  EXPECT_EQ(camera.pitch_degrees, -89.0f);
}

TEST(CameraControl, FramingPutsEveryPointInView) {
  const CovarianceMesh mesh = make_sample("torus");
  Camera camera;
  camera.yaw_degrees = 70.0f;
  const std::vector<int> some = {0, 5, 17, 40, 100};
  const Camera framed = frame_points(camera, mesh, some, 0.01);
  EXPECT_EQ(framed.yaw_degrees, 70.0f);
  for (const int v : some) {
    const Vec3 m = mesh.mean(size_t(v));
    const glm::vec2 p = pixel_of(framed, 500, 500, glm::vec3(float(m.x()), float(m.y()), float(m.z())));
    EXPECT_GE(p.x, 0.0f);
    EXPECT_LE(p.x, 500.0f);
    EXPECT_GE(p.y, 0.0f);
    EXPECT_LE(p.y, 500.0f);
  }
  EXPECT_EQ(frame_points(camera, mesh, {}, 0.01).distance, camera.distance);
}

}  // namespace
}  // namespace gps
