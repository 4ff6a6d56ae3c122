// The covariance ellipsoids of every vertex or of a chosen few (a dense mesh shows only the
// selection's and its neighbours').
#include <gtest/gtest.h>

#include "core/modelling/samples.h"
#include "render/pipeline/surface_renderer.h"
#include "tests/support/gl_fixture.h"
#include "view/camera.h"
#include "view/projection.h"

namespace gps {
namespace {

constexpr int kSize = 200;

class EllipsoidSubset : public test::GlTest {
protected:
  Image render(bool ellipsoids, const std::vector<int>* only) {
    DrawOptions o;
    o.level = 4;
    o.ellipsoids = ellipsoids;
    o.sigma_scale = 1.0f;
    o.ellipsoid_vertices = only;
    renderer_.draw(target_, camera_, o);
    return target_.read(0);
  }
  // The pixels where `a` and `b` differ.
  static std::vector<glm::vec2> changed(const Image& a, const Image& b) {
    std::vector<glm::vec2> out;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x)
        for (int c = 0; c < 3; ++c)
          if (a.at(x, y, c) != b.at(x, y, c)) {
            out.emplace_back(float(x), float(y));
            break;
          }
    return out;
  }
  CovarianceMesh mesh_ = make_sample("cube");
  void SetUp() override { renderer_.set_mesh(mesh_); }
  SurfaceRenderer renderer_;
  RenderTarget target_{kSize, kSize};
  Camera camera_ = frame_box(Vec3(-2, -2, -2), Vec3(2, 2, 2), 35.0f, 25.0f);
};

TEST_F(EllipsoidSubset, OnlyTheChosenVerticesEllipsoidsAreDrawn) {
  const Image none = render(false, nullptr), all = render(true, nullptr);
  const std::vector<int> one = {6}, empty, every = {0, 1, 2, 3, 4, 5, 6, 7}, two = {1, 6};
  // One vertex: every changed pixel lies within its ellipsoid's reach on screen.
  const auto p3 = project_to_pixel(camera_, kSize, kSize, to_glm(mesh_.mean(6)));
  ASSERT_TRUE(p3.has_value());
  const glm::vec2 p(*p3);
  const float sigma = float(std::sqrt(mesh_.covariance(6)(0, 0)));
  const auto q = project_to_pixel(camera_, kSize, kSize, to_glm(mesh_.mean(6)) + glm::vec3(0.0f, 1.2f * sigma, 0.0f));
  const float reach = glm::length(glm::vec2(*q) - p) + 2.0f;
  const auto by_one = changed(none, render(true, &one));
  EXPECT_GT(by_one.size(), 50u);
  for (const glm::vec2 pixel : by_one) ASSERT_LT(glm::length(pixel - p), 1.6f * reach) << pixel.x << ", " << pixel.y;
  EXPECT_GT(changed(none, all).size(), 3 * by_one.size()) << "all eight draw much more";
  EXPECT_TRUE(changed(none, render(true, &empty)).empty());
  EXPECT_TRUE(changed(all, render(true, &every)).empty()) << "every vertex listed: the same as all";
  EXPECT_GT(changed(none, render(true, &two)).size(), by_one.size());
}

}  // namespace
}  // namespace gps
