// Regression renders of the samples against stored images (tests/data/regression). A changed image
// fails and leaves NAME.actual.png and NAME.diff.png in the test's working folder. To accept new
// images on purpose: GPSURF_UPDATE_REGRESSION=1 ctest -R RegressionImages.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "core/io/mesh_io.h"
#include "core/modelling/samples.h"
#include "render/image/image_io.h"
#include "render/pipeline/render_framing.h"
#include "render/pipeline/surface_renderer.h"
#include "tests/support/gl_fixture.h"

namespace gps {
namespace {

Image render_sample(SurfaceRenderer& renderer, const std::string& name) {
  // Creased meshes are data files (tests/data), the rest built-in samples.
  const CovarianceMesh mesh = name.rfind("creased", 0) == 0
                                  ? read_mesh(std::string(GPS_TEST_DATA_DIR) + "/" + name + ".ply")
                                  : make_sample(name);
  renderer.set_mesh(mesh);
  RenderTarget target(128, 128);
  DrawOptions o;
  o.level = 8;
  o.mesh_lines = true;
  renderer.draw(target, render_camera(renderer, mesh, {35.0f, 25.0f}, 1, o, 128, 128), o);
  Image rgba = target.read(0), rgb{rgba.width, rgba.height, 3, {}};
  for (size_t i = 0; i < rgba.pixels.size(); i += 4)
    rgb.pixels.insert(rgb.pixels.end(), rgba.pixels.begin() + long(i), rgba.pixels.begin() + long(i) + 3);
  return rgb;
}

using RegressionImages = test::GlTest;

TEST_F(RegressionImages, SamplesRenderAsStored) {
  SurfaceRenderer renderer;
  const bool update = std::getenv("GPSURF_UPDATE_REGRESSION") != nullptr;
  for (const char* name : {"cube", "cone", "cone-pointy", "cone-concave", "cone-plateau", "cone-cylinder", "wirecube",
                           "valence5", "valence8", "cylinder", "creased_cube", "creased_cylinder",
                           "creased_cone"}) {
    const Image actual = render_sample(renderer, name);
    const std::string stored = std::string(GPS_TEST_DATA_DIR) + "/regression/" + name + ".png";
    if (update) {
      write_image(stored, actual);
      continue;
    }
    ASSERT_TRUE(std::filesystem::exists(stored)) << stored << " is missing (GPSURF_UPDATE_REGRESSION=1 makes it)";
    const Image expected = read_image(stored);
    ASSERT_EQ(expected.width, actual.width);
    ASSERT_EQ(expected.height, actual.height);
    Image diff{actual.width, actual.height, 3, std::vector<float>(actual.pixels.size(), 0.0f)};
    int changed = 0;
    for (int y = 0; y < actual.height; ++y)
      for (int x = 0; x < actual.width; ++x) {
        float worst = 0;
        for (int c = 0; c < 3; ++c)
          worst = std::max(worst, std::abs(actual.at(x, y, c) - expected.at(x, y, std::min(c, expected.channels - 1))));
        diff.pixels[(size_t(y) * size_t(actual.width) + size_t(x)) * 3] = std::min(1.0f, worst * 8.0f);
        changed += worst > 10.0f / 255.0f;
      }
    const double share = double(changed) / (actual.width * actual.height);
    if (share > 0.002) {
      write_image(std::string(name) + ".actual.png", actual);
      write_image(std::string(name) + ".diff.png", diff);
    }
    EXPECT_LE(share, 0.002) << name << ": " << changed << " pixels changed; see "
                            << std::filesystem::current_path().string() << "/" << name << ".diff.png";
  }
}

}  // namespace
}  // namespace gps
