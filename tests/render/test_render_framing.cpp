// The camera of a render (render/pipeline/render_framing.h) on surfaces that perspective magnifies:
// the cube with one vertex's Gaussian made small pulls its surface into an egg or a needle whose end
// faces the default view. Tessellated finely for the framed camera, the surface lies wholly inside
// the image and in front of the near plane, and still fills a good part of it.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/modelling/samples.h"
#include "render/pipeline/render_framing.h"
#include "render/pipeline/surface_renderer.h"
#include "tests/support/gl_fixture.h"
#include "view/silhouette_framing.h"

namespace gps {
namespace {

using RenderFraming = test::GlTest;

TEST_F(RenderFraming, ASurfaceThatFacesTheEyeStaysWholeInTheImage) {
  for (const double sigma2 : {1e-2, 1e-3, 1e-6})
    for (const auto& [width, height] : {std::pair{800, 600}, std::pair{600, 800}}) {
      const std::string what =
          "covariance " + std::to_string(sigma2) + ", " + std::to_string(width) + "x" + std::to_string(height);
      CovarianceMesh mesh = make_sample("cube");
      mesh.set_covariance(0, sigma2 * Mat3::Identity());
      SurfaceRenderer renderer;
      renderer.set_mesh(mesh);
      DrawOptions adaptive;
      adaptive.pixels = 6.0f;  // `gpsurf render`'s default
      const Camera camera = render_camera(renderer, mesh, {}, 1, adaptive, width, height);
      DrawOptions fine;
      fine.pixels = 1.0f;
      std::vector<glm::dvec3> points;
      for (const TessellatedVertex& v : renderer.capture_vertices(camera, fine, width, height))
        points.emplace_back(v.position[0], v.position[1], v.position[2]);
      ASSERT_FALSE(points.empty()) << what;
      const double aspect = double(width) / height;
      const NdcRect bounds = projected_bounds(camera, points, aspect);
      EXPECT_GE(std::min(bounds.lo.x, bounds.lo.y), -1.0) << what << ": the surface leaves the image";
      EXPECT_LE(std::max(bounds.hi.x, bounds.hi.y), 1.0) << what << ": the surface leaves the image";
      EXPECT_GT(std::max(bounds.hi.x - bounds.lo.x, bounds.hi.y - bounds.lo.y), 1.0) << what << ": drawn small";
      // In front of the near plane (view/camera.cpp: a hundredth of the distance), with room to spare.
      const glm::dvec3 eye = camera.eye_double(), forward = glm::normalize(camera.target - eye);
      double nearest = camera.distance;
      for (const glm::dvec3& p : points) nearest = std::min(nearest, glm::dot(p - eye, forward));
      EXPECT_GT(nearest, 0.05 * camera.distance) << what << ": the near plane cuts the surface";
    }
}

}  // namespace
}  // namespace gps
