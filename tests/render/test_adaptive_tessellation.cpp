// Adaptive tessellation levels (shaders/tess_levels.glsl) on OSMesa: an edge seen end-on still gets
// the level its size on screen asks for, so that the silhouette of an orthographic axis view, which
// runs beside such edges, is as smooth as at a high uniform level.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "core/modelling/samples.h"
#include "render/gl/render_target.h"
#include "render/image/image_io.h"
#include "render/pipeline/surface_renderer.h"
#include "tests/support/gl_fixture.h"
#include "view/camera.h"

namespace gps {
namespace {

using GpuTest = test::GlTest;

// Where the surface was drawn: the position AOV's coverage (w ≥ 1).
std::vector<char> coverage_of(const Image& position) {
  std::vector<char> covered(size_t(position.width) * size_t(position.height));
  for (int y = 0; y < position.height; ++y)
    for (int x = 0; x < position.width; ++x)
      covered[size_t(y) * size_t(position.width) + size_t(x)] = position.at(x, y, 3) >= 1.0f;
  return covered;
}

// Pixels covered by exactly one of the two masks, and those covered by `a`, as a grey image (white:
// covered by `a`; black and white swapped where the masks differ) for looking at.
struct MaskDifference {
  long long differing = 0, covered = 0;
  Image image;
};

MaskDifference difference(const std::vector<char>& a, const std::vector<char>& b, int width, int height) {
  MaskDifference d;
  d.image.width = width;
  d.image.height = height;
  d.image.channels = 3;
  d.image.pixels.assign(size_t(width) * size_t(height) * 3, 0.0f);
  for (size_t i = 0; i < a.size(); ++i) {
    d.covered += a[i];
    d.differing += a[i] != b[i];
    const float grey = a[i] != b[i] ? 0.5f : a[i] ? 1.0f : 0.0f;
    for (size_t c = 0; c < 3; ++c) d.image.pixels[3 * i + c] = grey;
  }
  return d;
}

// The cube sample from the front in the editor's orthographic axis view (numpad 1, then 5) in its
// default window: the patch edges along the view direction project to a point. Their level must
// still follow their size, or the side patches, whose silhouette runs across them, are cut into a
// polygon of a few segments, with notches where the uniform render is round.
TEST_F(GpuTest, EdgesSeenEndOnKeepTheSilhouetteOfAnOrthographicAxisView) {
  const CovarianceMesh mesh = make_sample("cube");
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh);
  Camera camera = frame_mesh(mesh, 0.0f, 0.0f);
  camera.orthographic = true;
  const int width = 1280, height = 800;
  RenderTarget target(width, height);
  const auto coverage = [&](const DrawOptions& o) {
    renderer.draw(target, camera, o);
    return std::pair{coverage_of(target.read(1)), target.read(0)};
  };
  DrawOptions adaptive;
  adaptive.pixels = 6.0f;  // the editor's default
  DrawOptions fine;
  fine.level = 32.0f;
  const auto [adaptive_mask, adaptive_color] = coverage(adaptive);
  const auto [fine_mask, fine_color] = coverage(fine);
  const MaskDifference d = difference(fine_mask, adaptive_mask, width, height);
  if (std::getenv("GPS_KEEP_IMAGES")) {
    write_image("adaptive_front_ortho.png", adaptive_color);
    write_image("uniform_front_ortho.png", fine_color);
    write_image("adaptive_front_ortho_difference.png", d.image);
  }
  ASSERT_GT(d.covered, width * height / 20) << "the cube fills much of the view";
  // Both silhouettes are round: they differ by rasterisation alone, a few pixels along the outline.
  std::printf("coverage: %lld pixels, %lld differ between adaptive and uniform level 32\n", d.covered, d.differing);
  EXPECT_LE(d.differing, 40);
}

}  // namespace
}  // namespace gps
