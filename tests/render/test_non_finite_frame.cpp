// A frame with non-finite output is found (render/image/non_finite_pixels.h): `gpsurf render`
// reports it instead of writing an image.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/modelling/samples.h"
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

}  // namespace
}  // namespace gps
