// The base-mesh cage is drawn with depth: where the surface hides it, it is faint
// (kHiddenCageAlpha over the surface); where it is in front, at full strength.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/modelling/samples.h"
#include "render/image/image_io.h"
#include "render/pipeline/surface_renderer.h"
#include "tests/support/gl_fixture.h"
#include "view/camera.h"
#include "view/projection.h"

namespace gps {
namespace {

constexpr int kSize = 240;
const glm::vec3 kCage(0.45f);  // the cage's colour

struct Shots {
  Image plain, caged;
};

Shots render(const CovarianceMesh& mesh, const Camera& camera) {
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh);
  RenderTarget target(kSize, kSize);
  DrawOptions o;
  o.level = 8;
  o.mode = ShadingMode::flat;
  renderer.draw(target, camera, o);
  Shots s;
  s.plain = target.read(0);
  o.mesh_lines = true;
  renderer.draw(target, camera, o);
  s.caged = target.read(0);
  return s;
}

glm::vec3 at(const Image& im, int x, int y) { return {im.at(x, y, 0), im.at(x, y, 1), im.at(x, y, 2)}; }

// Over the pixels around `pixel`, the largest share of the way from the plain render to the cage's
// colour that drawing the cage went (1: the cage colour itself, 0: untouched).
float cage_strength(const Shots& s, glm::vec2 pixel) {
  float strongest = 0.0f;
  for (int y = int(pixel.y) - 1; y <= int(pixel.y) + 1; ++y)
    for (int x = int(pixel.x) - 1; x <= int(pixel.x) + 1; ++x) {
      if (x < 0 || y < 0 || x >= kSize || y >= kSize) continue;
      const glm::vec3 plain = at(s.plain, x, y), caged = at(s.caged, x, y), to_cage = kCage - plain;
      if (glm::length(to_cage) < 0.08f) continue;  // the surface is cage-coloured here: nothing to tell
      strongest = std::max(strongest, glm::dot(caged - plain, to_cage) / glm::dot(to_cage, to_cage));
    }
  return strongest;
}

using CageDepth = test::GlTest;

// Looking down the cube's diagonal, its back corner (−1, −1, −1) lies right behind the rounded
// limit surface and its front corner (1, 1, 1) right before it; their edges project 60° apart.
// Compared a little way along one edge of each, away from the corners where lines overlap.
TEST_F(CageDepth, EdgesBehindTheSurfaceAreFaintAndThoseInFrontFull) {
  Camera camera;
  camera.yaw_degrees = 45.0f;
  camera.pitch_degrees = glm::degrees(std::asin(1.0f / std::sqrt(3.0f)));
  camera.distance = 6.0f;
  const Shots s = render(make_sample("cube"), camera);
  if (std::getenv("GPS_KEEP_IMAGES")) write_image("cage_depth.png", s.caged);
  const auto back = project_to_pixel(camera, kSize, kSize, glm::vec3(-0.7f, -1.0f, -1.0f));
  const auto front = project_to_pixel(camera, kSize, kSize, glm::vec3(0.7f, 1.0f, 1.0f));
  ASSERT_TRUE(back && front);
  EXPECT_GT(cage_strength(s, *front), 0.97f) << "the edges in front are drawn at full strength";
  EXPECT_GT(cage_strength(s, *back), 0.5f * kHiddenCageAlpha) << "the hidden edges still show";
  EXPECT_LT(cage_strength(s, *back), 1.5f * kHiddenCageAlpha)
      << "the hidden edges are drawn through the surface at full strength";
  // The faint lines are blended in colour only: the image stays opaque (no see-through lines once
  // written to a file or shown over another background).
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) ASSERT_EQ(s.caged.at(x, y, 3), s.plain.at(x, y, 3)) << x << ", " << y;
}

// Where no surface lies behind a line it is not hidden: the cube's cage, outside its small rounded
// surface, is drawn in full at its front corner.
TEST_F(CageDepth, EdgesOverTheBackgroundAreFull) {
  const CovarianceMesh mesh = make_sample("cube");
  const Camera camera = frame_box(Vec3(-1.6, -1.6, -1.6), Vec3(1.6, 1.6, 1.6), 35.0f, 25.0f);
  const auto p = project_to_pixel(camera, kSize, kSize, glm::vec3(1.0f, -1.0f, 1.0f));
  ASSERT_TRUE(p.has_value());
  EXPECT_GT(cage_strength(render(mesh, camera), *p), 0.97f);
}

}  // namespace
}  // namespace gps
