// Picking: rays through pixels, vertices near the mouse, the surface point under a pixel (OSMesa).
#include "render/pipeline/surface_point.h"
#include "view/picking.h"

#include <gtest/gtest.h>

#include "core/modelling/samples.h"
#include "render/pipeline/surface_renderer.h"
#include "tests/support/gl_fixture.h"

namespace gps {
namespace {

glm::vec3 mean_of(const CovarianceMesh& mesh, size_t i) {
  const Vec3 m = mesh.mean(i);
  return {float(m.x()), float(m.y()), float(m.z())};
}

Camera cube_camera() { return frame_box(Vec3(-1, -1, -1), Vec3(1, 1, 1), 35.0f, 25.0f); }

using Picking = test::GlTest;

TEST_F(Picking, RaysThroughAProjectedPointHitIt) {
  const CovarianceMesh mesh = make_sample("cube");
  const Camera camera = cube_camera();
  for (size_t i = 0; i < mesh.n_vertices(); ++i) {
    const glm::vec3 world = mean_of(mesh, i);
    const auto p = project_to_pixel(camera, 200, 150, world);
    ASSERT_TRUE(p.has_value());
    const Ray ray = pixel_ray(camera, 200, 150, glm::vec2(*p) - glm::vec2(0.5f));
    const glm::dvec3 to_point = glm::dvec3(world) - ray.origin;
    const double off_ray = glm::length(to_point - glm::dot(to_point, ray.direction) * ray.direction);
    EXPECT_LT(off_ray, 1e-4 * glm::length(to_point)) << "vertex " << i;
    EXPECT_GT(glm::dot(to_point, ray.direction), 0.0);
  }
}

TEST_F(Picking, PicksTheVertexUnderTheMouseAndNothingElsewhere) {
  const CovarianceMesh mesh = make_sample("cube");
  const Camera camera = cube_camera();
  for (size_t i = 0; i < mesh.n_vertices(); ++i) {
    const auto p = project_to_pixel(camera, 200, 150, mean_of(mesh, i));
    ASSERT_TRUE(p.has_value());
    // Three pixels off to the side still picks it; the pixel centre convention matches pixel_ray.
    EXPECT_EQ(pick_vertex(camera, 200, 150, glm::vec2(p->x + 2.5f, p->y - 0.5f), mesh, 6.0f), int(i));
  }
  EXPECT_EQ(pick_vertex(camera, 200, 150, glm::vec2(1.0f, 1.0f), mesh, 6.0f), -1);
  // Seen along a diagonal, (1,1,1) hides (-1,-1,-1) exactly: the front one wins.
  Camera diagonal = camera;
  diagonal.target = glm::vec3(0.0f);
  diagonal.yaw_degrees = 45.0f;
  diagonal.pitch_degrees = glm::degrees(std::asin(1.0f / std::sqrt(3.0f)));
  int front = -1;
  for (size_t i = 0; i < mesh.n_vertices(); ++i)
    if (mesh.mean(i).minCoeff() > 0) front = int(i);
  EXPECT_EQ(pick_vertex(diagonal, 100, 100, glm::vec2(49.5f, 49.5f), mesh, 4.0f), front);
}

TEST_F(Picking, SurfacePointUnderAPixelLiesOnTheRay) {
  const CovarianceMesh mesh = make_sample("cube");
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh);
  RenderTarget target(96, 64);
  const Camera camera = cube_camera();
  DrawOptions o;
  o.level = 16;
  renderer.draw(target, camera, o);
  EXPECT_FALSE(surface_point(target, glm::vec2(1.0f, 1.0f)).has_value());
  EXPECT_FALSE(surface_point(target, glm::vec2(-1.0f, 10.0f)).has_value());
  int hits = 0;
  for (const glm::vec2 pixel : {glm::vec2(48, 32), glm::vec2(40, 28), glm::vec2(55, 38)}) {
    const auto point = surface_point(target, pixel);
    ASSERT_TRUE(point.has_value()) << pixel.x << "," << pixel.y;
    ++hits;
    // The point lies inside the cube's hull, on the ray through that pixel, in front of the eye.
    EXPECT_LE(glm::length(*point), std::sqrt(3.0f) + 1e-3f);
    const Ray ray = pixel_ray(camera, 96, 64, pixel);
    const glm::dvec3 to_point = glm::dvec3(*point) - ray.origin;
    const double along = glm::dot(to_point, ray.direction);
    EXPECT_GT(along, 0.0);
    // Within a pixel's footprint at that distance.
    const double footprint = 2.0 * along * std::tan(glm::radians(double(camera.fov_degrees)) * 0.5) / 64.0;
    EXPECT_LT(glm::length(to_point - along * ray.direction), footprint);
  }
  EXPECT_EQ(hits, 3);
}

// Projection, rays and picking commute with moving the mesh and its framing camera: the torus moved
// by 1e7 (where a float holds a coordinate to about one unit, a sixth of the torus) or scaled by 1e-6
// or 1e10 projects, casts rays and picks as at the origin at unit scale.
TEST_F(Picking, AFarOrScaledTorusIsPickedAsAtTheOrigin) {
  const CovarianceMesh torus = make_sample("torus");
  const Camera camera = frame_mesh(torus, 35.0f, 25.0f);
  const int w = 320, h = 240;
  for (const auto& [scale, offset] : {std::pair{1.0, Vec3(1e7, -3e7, 2e7)}, std::pair{1e-6, Vec3(1e-3, 0, 0)},
                                      std::pair{1e10, Vec3(0, 0, 0)}}) {
    CovarianceMesh moved = torus;
    for (size_t i = 0; i < torus.n_vertices(); ++i) moved.set_mean(i, scale * torus.mean(i) + offset);
    const Camera moved_camera = frame_mesh(moved, 35.0f, 25.0f);
    const double diagonal = bounding_box_diagonal(moved);
    int compared = 0;
    for (size_t i = 0; i < torus.n_vertices(); i += 7) {
      const auto p = visible_pixel(camera, w, h, torus.mean(i)), q = visible_pixel(moved_camera, w, h, moved.mean(i));
      ASSERT_TRUE(p && q) << "scale " << scale << " vertex " << i;
      EXPECT_LT(glm::length(glm::vec2(*p) - glm::vec2(*q)), 0.01f) << "scale " << scale << " vertex " << i;
      const glm::vec2 pixel = glm::vec2(*q) - glm::vec2(0.5f);
      EXPECT_EQ(pick_vertex(moved_camera, w, h, pixel, moved, 4.0f), pick_vertex(camera, w, h, pixel, torus, 4.0f))
          << "scale " << scale << " vertex " << i;
      // The ray through the vertex's pixel passes through it, to a pixel's fraction.
      const Ray ray = pixel_ray(moved_camera, w, h, pixel);
      const Vec3 to_point = moved.mean(i) - to_vec(ray.origin), direction = to_vec(ray.direction);
      EXPECT_LT((to_point - to_point.dot(direction) * direction).norm(), 1e-4 * diagonal)
          << "scale " << scale << " vertex " << i;
      ++compared;
    }
    EXPECT_GT(compared, 30);
  }
}

}  // namespace
}  // namespace gps

namespace gps {
namespace {

// A ray through any pixel inside a vertex's projected k-sigma ellipsoid picks it, for any camera
// and window size; a pixel well outside every ellipsoid picks nothing.
TEST_F(Picking, EllipsoidsArePickedExactlyWhereTheyProject) {
  CovarianceMesh mesh = make_sample("cube");
  for (size_t i = 0; i < mesh.n_vertices(); ++i) mesh.covariances[i] = Vec3(0.01, 0.0025, 0.04).asDiagonal();
  for (const auto& [w, h, yaw] :
       {std::tuple{640, 480, 30.0f}, std::tuple{300, 900, 120.0f}, std::tuple{1500, 500, -60.0f}}) {
    const Camera camera = frame_box(Vec3(-1.5, -1.5, -1.5), Vec3(1.5, 1.5, 1.5), yaw, 25.0f);
    for (size_t v = 0; v < mesh.n_vertices(); ++v) {
      // A point on the 2-sigma ellipsoid's silhouette-facing side: μ + 1.9 σ_z ẑ lies inside it.
      const Vec3 inside = mesh.mean(v) + Vec3(0, 0, 1.9 * 0.2);
      const auto p = project_to_pixel(camera, w, h, glm::vec3(float(inside.x()), float(inside.y()), float(inside.z())));
      ASSERT_TRUE(p.has_value());
      const int picked = pick_ellipsoid(camera, w, h, glm::vec2(*p) - glm::vec2(0.5f), mesh, 2.0);
      // Another ellipsoid may lie in front along that ray: then the picked one must be nearer the eye.
      ASSERT_GE(picked, 0);
      if (picked != int(v)) {
        const glm::vec3 eye = camera.eye();
        const Vec3 e(eye.x, eye.y, eye.z);
        EXPECT_LT((mesh.mean(size_t(picked)) - e).norm(), (mesh.mean(v) - e).norm());
      }
    }
    EXPECT_EQ(pick_ellipsoid(camera, w, h, glm::vec2(1.0f, 1.0f), mesh, 2.0), -1);
  }
}

}  // namespace
}  // namespace gps
