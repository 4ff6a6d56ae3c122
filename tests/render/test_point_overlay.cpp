// Points over the surface (render/overlays/point_overlay.h): a point on the limit surface facing the
// camera shows in its distance's ramp colour, one on the far side is hidden by the surface, one
// floating before it shows; before their distances are set the points are grey; and points drawn
// far from the origin keep their place (the overlay's frame).
#include <gtest/gtest.h>

#include <cstdlib>

#include "core/fitting/surface_distance.h"
#include "core/modelling/samples.h"
#include "render/image/image_io.h"
#include "render/overlays/distance_ramp.h"
#include "render/overlays/point_overlay.h"
#include "render/pipeline/surface_renderer.h"
#include "tests/support/gl_fixture.h"
#include "view/camera.h"
#include "view/projection.h"

namespace gps {
namespace {

constexpr int kSize = 240;

glm::vec3 at(const Image& im, glm::vec2 p) {
  const int x = int(p.x), y = int(p.y);
  return {im.at(x, y, 0), im.at(x, y, 1), im.at(x, y, 2)};
}

// The limit surface's point nearest the ray from its centre along `direction` (a vertex of a fine tessellation).
Vec3 surface_point(const TriangleMesh& limit, const Vec3& direction) {
  Vec3 best = limit.positions.front();
  for (const Vec3& p : limit.positions)
    if (p.normalized().dot(direction) > best.normalized().dot(direction)) best = p;
  return best;
}

struct Scene {
  Image shot;
  glm::vec2 front, back, floating;
};

// A sphere seen along +z, with a point on its front, one on its back and one before it at `offset`,
// their distances 0, 0 and 1 on a ramp ending at 2 (unless `unmeasured`), all moved by `shift`.
Scene draw(bool unmeasured, const Vec3& shift = Vec3::Zero()) {
  CovarianceMesh mesh = make_sample("icosphere", 320);
  for (size_t v = 0; v < mesh.n_vertices(); ++v) mesh.set_mean(v, mesh.mean(v) + shift);
  const TriangleMesh limit = limit_surface_triangles(make_sample("icosphere", 320), 6).triangles;
  const Vec3 front = surface_point(limit, Vec3(0.3, 0.2, 1.0).normalized()),
             back = surface_point(limit, Vec3(0.3, 0.2, -1.0).normalized()),
             floating = 1.4 * surface_point(limit, Vec3(-0.4, -0.3, 1.0).normalized());
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh);
  PointOverlay points;
  points.set_points({front + shift, back + shift, floating + shift}, renderer.frame());
  if (!unmeasured) points.set_distances({0.0f, 0.0f, 1.0f});
  Camera camera = frame_mesh(mesh, 0.0f, 0.0f);
  RenderTarget target(kSize, kSize);
  DrawOptions o;
  o.level = 12;
  o.mode = ShadingMode::flat;
  renderer.draw(target, camera, o);
  PointOverlay::Style style;
  style.max_distance = 2.0;
  style.point_size = 9.0f;
  points.draw(target, camera, style);
  Scene s;
  s.shot = target.read(0);
  const auto pixel = [&](const Vec3& p) {
    const auto q = project_to_pixel(camera, kSize, kSize, Vec3(p + shift));
    EXPECT_TRUE(q.has_value());
    return q ? glm::vec2(*q) : glm::vec2(0.0f);
  };
  s.front = pixel(front), s.back = pixel(back), s.floating = pixel(floating);
  if (std::getenv("GPS_KEEP_IMAGES")) write_image(unmeasured ? "points_unmeasured.png" : "points.png", s.shot);
  return s;
}

using PointOverlayTest = test::GlTest;

TEST_F(PointOverlayTest, OnTheSurfaceAndBeforeItShownBehindItHidden) {
  const Scene s = draw(false);
  EXPECT_LT(glm::length(at(s.shot, s.front) - ramp_colour(0.0f)), 0.03f) << "the point on the surface";
  EXPECT_LT(glm::length(at(s.shot, s.floating) - ramp_colour(0.5f)), 0.03f) << "the point before it";
  for (float t = 0.0f; t <= 1.0f; t += 0.05f)
    EXPECT_GT(glm::length(at(s.shot, s.back) - ramp_colour(t)), 0.1f) << "the point behind it, at " << t;
}

TEST_F(PointOverlayTest, GreyUntilMeasured) {
  const Scene s = draw(true);
  const glm::vec3 c = at(s.shot, s.front);
  EXPECT_NEAR(c.r, c.g, 0.01f);
  EXPECT_NEAR(c.g, c.b, 0.01f);
  EXPECT_GT(c.r, 0.7f);
}

TEST_F(PointOverlayTest, FarFromTheOriginInPlace) {
  const Scene s = draw(false, Vec3(3e5, -2e5, 1e5));
  EXPECT_LT(glm::length(at(s.shot, s.front) - ramp_colour(0.0f)), 0.03f);
  EXPECT_LT(glm::length(at(s.shot, s.floating) - ramp_colour(0.5f)), 0.03f);
}

}  // namespace
}  // namespace gps
