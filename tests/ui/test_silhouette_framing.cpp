// Framing by projected bounds (view/silhouette_framing.h), checked through the camera's own
// view-projection: the points fill the asked region along one axis and are centred along the other.
#include "view/silhouette_framing.h"

#include <gtest/gtest.h>

#include "core/modelling/samples.h"
#include "ui/input/camera_control.h"

namespace gps {
namespace {

std::vector<glm::dvec3> means_of(const CovarianceMesh& mesh) {
  std::vector<glm::dvec3> points;
  for (size_t i = 0; i < mesh.n_vertices(); ++i)
    points.emplace_back(mesh.mean(i).x(), mesh.mean(i).y(), mesh.mean(i).z());
  return points;
}

// The bounds of `points` seen by `camera` lie in `region` shrunk by `margin`, touch it on both sides
// along one axis and are centred in it along the other.
void expect_framed(const Camera& camera, const std::vector<glm::dvec3>& points, double aspect, const NdcRect& region,
                   double margin, const std::string& what) {
  const NdcRect b = projected_bounds(camera, points, aspect);
  const glm::dvec2 mid = 0.5 * (region.lo + region.hi), half = 0.5 * (region.hi - region.lo) * (1.0 - margin);
  int tight = 0;
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(0.5 * (b.lo[k] + b.hi[k]), mid[k], 1e-5) << what << " axis " << k << " not centred";
    EXPECT_LE(0.5 * (b.hi[k] - b.lo[k]), half[k] + 1e-5) << what << " axis " << k << " outside";
    tight += std::abs(0.5 * (b.hi[k] - b.lo[k]) - half[k]) < 1e-5;
  }
  EXPECT_GE(tight, 1) << what << ": the bounds fill neither axis";
}

TEST(SilhouetteFraming, TheProjectedBoundsFillTheImageAtAnyAnglesAndAspect) {
  for (const char* name : {"cone", "cube", "cylinder", "torus"}) {
    const std::vector<glm::dvec3> points = means_of(make_sample(name));
    for (const int up : {0, 1, 2})
      for (const glm::vec2 angles : {glm::vec2(30, 20), glm::vec2(-70, 55), glm::vec2(180, -10)})
        for (const double aspect : {4.0 / 3.0, 0.5, 1.0}) {
          Camera camera;
          camera.yaw_degrees = angles.x, camera.pitch_degrees = angles.y, camera.up_axis = up;
          const Camera framed = frame_silhouette(camera, points, aspect);
          EXPECT_EQ(framed.yaw_degrees, camera.yaw_degrees);
          EXPECT_EQ(framed.up_axis, up);
          expect_framed(framed, points, aspect, NdcRect{}, 0.05, std::string(name) + " up " + std::to_string(up));
        }
  }
}

TEST(SilhouetteFraming, FillsAPartOfTheImageInPerspectiveAndOrthographic) {
  const std::vector<glm::dvec3> points = means_of(make_sample("cone-pointy"));
  const NdcRect region = ndc_of_pixels({1024, 700}, {0, 21}, {646, 675});
  EXPECT_NEAR(region.lo.x, -1.0, 1e-12);
  EXPECT_NEAR(region.hi.x, 2.0 * 646 / 1024 - 1.0, 1e-12);
  EXPECT_NEAR(region.hi.y, 1.0 - 2.0 * 21 / 700, 1e-12);
  for (const bool orthographic : {false, true}) {
    Camera camera;
    camera.orthographic = orthographic;
    const Camera framed = frame_silhouette(camera, points, 1024.0 / 700.0, region, 0.1);
    EXPECT_EQ(framed.orthographic, orthographic);
    expect_framed(framed, points, 1024.0 / 700.0, region, 0.1, orthographic ? "orthographic" : "perspective");
  }
}

// The old framing put a sphere around the bounding box in view: the silhouette now spans more of the
// image, and the editor's region framing of every vertex is the same framing.
TEST(SilhouetteFraming, SpansMoreThanTheBoundingSphereAndDrivesTheEditorsFraming) {
  const CovarianceMesh cone = make_sample("cone");
  const std::vector<glm::dvec3> points = means_of(cone);
  const NdcRect sphere = projected_bounds(frame_mesh(cone), points, 4.0 / 3.0);
  const NdcRect tight = projected_bounds(frame_silhouette(frame_mesh(cone), points, 4.0 / 3.0), points, 4.0 / 3.0);
  EXPECT_GT(tight.hi.y - tight.lo.y, 1.3 * (sphere.hi.y - sphere.lo.y));

  std::vector<int> all(cone.n_vertices());
  for (size_t i = 0; i < all.size(); ++i) all[i] = int(i);
  const Camera home = frame_points_in_region(Camera{}, cone, all, 0.0, {800, 600}, {100, 50}, {500, 550});
  expect_framed(home, points, 800.0 / 600.0, ndc_of_pixels({800, 600}, {100, 50}, {500, 550}), 0.05, "region");
}

// A needle seen end on: framed to fill the image the eye would sit on its tip. It stays a tenth of the
// needle's length in front of it instead, the needle centred along both axes and inside the image.
TEST(SilhouetteFraming, TheEyeStaysClearOfANeedleSeenEndOn) {
  Camera camera;
  const glm::dvec3 forward = -glm::normalize(camera.eye_offset());
  const glm::dvec3 side = glm::normalize(glm::cross(forward, glm::dvec3(0, 1, 0)));
  const double length = 2.0;
  std::vector<glm::dvec3> points;
  for (int i = 0; i <= 100; ++i) {
    const double t = i / 100.0, radius = 0.01 * std::sqrt(t);  // from its tip near the eye
    for (const double s : {-1.0, 1.0}) points.push_back(t * length * forward + s * radius * side);
  }
  const Camera framed = frame_silhouette(camera, points, 4.0 / 3.0);
  const glm::dvec3 eye = framed.eye_double(), view = glm::normalize(framed.target - eye);
  double nearest = length;
  for (const glm::dvec3& p : points) nearest = std::min(nearest, glm::dot(p - eye, view));
  EXPECT_GT(nearest, 0.099 * length);
  const NdcRect b = projected_bounds(framed, points, 4.0 / 3.0);
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(b.lo[k] + b.hi[k], 0.0, 1e-6) << "axis " << k << " not centred";
    EXPECT_LT(b.hi[k], 0.95 + 1e-6) << "axis " << k << " outside";
  }
}

TEST(SilhouetteFraming, OnePointKeepsTheDistanceAndNoPointsKeepTheCamera) {
  Camera camera;
  camera.distance = 3.0f;
  const Camera one = frame_silhouette(camera, {glm::dvec3(1, 2, 3)}, 1.0);
  EXPECT_FLOAT_EQ(one.distance, 3.0f);
  EXPECT_LT(glm::length(glm::dvec3(one.target) - glm::dvec3(1, 2, 3)), 1e-5);
  EXPECT_EQ(frame_silhouette(camera, {}, 1.0).distance, 3.0f);
}

}  // namespace
}  // namespace gps
