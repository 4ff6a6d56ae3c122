// A frame with non-finite output is found (render/image/non_finite_pixels.h): `gpsurf render`
// reports it instead of writing an image; the editor counts the same pixels on the GPU
// (render/gl/frame_finite_check.h).
#include <glad/gl.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/modelling/samples.h"
#include "render/gl/frame_finite_check.h"
#include "render/gl/render_target.h"
#include "render/image/non_finite_pixels.h"
#include "render/pipeline/surface_renderer.h"
#include "tests/support/gl_fixture.h"
#include "view/camera.h"

namespace gps {
namespace {

using NonFiniteFrame = test::GlTest;

TEST_F(NonFiniteFrame, CountsThePixelsWhoseAovsAreNotFinite) {
  const CovarianceMesh torus = make_sample("torus");
  SurfaceRenderer renderer;
  renderer.set_mesh(torus);
  RenderTarget target(64, 64);
  DrawOptions o;
  o.level = 4;
  o.pixels = 0;
  renderer.draw(target, frame_mesh(torus), o);
  Image position = target.read(1), normal = target.read(2);
  EXPECT_EQ(count_non_finite_pixels(position, normal), 0);
  // A NaN position at the centre (covered) and an infinite normal elsewhere.
  ASSERT_GT(position.at(32, 32, 3), 0.5f);
  const auto at = [](Image& image, int x, int y, int c) -> float& {
    return image.pixels[(size_t(y) * size_t(image.width) + size_t(x)) * size_t(image.channels) + size_t(c)];
  };
  at(position, 32, 32, 1) = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(count_non_finite_pixels(position, normal), 1);
  at(normal, 3, 60, 2) = std::numeric_limits<float>::infinity();
  EXPECT_EQ(count_non_finite_pixels(position, normal), 2);
}

// The GPU's count equals the count of the images read back, with a NaN position, an infinite normal
// and a pixel with both (counted once).
TEST_F(NonFiniteFrame, TheGpuCountsWhatTheReadBackImagesShow) {
  const CovarianceMesh torus = make_sample("torus");
  SurfaceRenderer renderer;
  renderer.set_mesh(torus);
  RenderTarget target(70, 45);  // not a whole number of the count's 16 × 16 tiles
  DrawOptions o;
  o.level = 4;
  o.pixels = 0;
  renderer.draw(target, frame_mesh(torus), o);
  const FrameFiniteCheck check;
  EXPECT_EQ(check.non_finite_pixels(target), 0);
  const auto set = [&](int attachment, int x, int y, float value) {
    const float pixel[4] = {value, 0.0f, value, 1.0f};
    glTextureSubImage2D(target.texture(attachment), 0, x, y, 1, 1, GL_RGBA, GL_FLOAT, pixel);
  };
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  set(1, 35, 22, nan);
  set(2, 69, 44, -inf);
  set(1, 0, 0, inf);
  set(2, 0, 0, nan);
  EXPECT_EQ(check.non_finite_pixels(target), 3);
  EXPECT_EQ(count_non_finite_pixels(target.read(1), target.read(2)), 3);
}

}  // namespace
}  // namespace gps
