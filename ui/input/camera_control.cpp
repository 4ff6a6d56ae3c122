#include "ui/input/camera_control.h"

#include <algorithm>
#include <cmath>

#include "view/projection.h"
#include "view/silhouette_framing.h"

namespace gps {

void orbit(Camera& camera, glm::vec2 delta) {
  camera.yaw_degrees = std::fmod(camera.yaw_degrees - 0.4f * delta.x, 360.0f);
  camera.pitch_degrees = std::clamp(camera.pitch_degrees + 0.4f * delta.y, -89.0f, 89.0f);
}

void pan(Camera& camera, glm::vec2 delta, int height) {
  const glm::dmat4 view = camera.view_double();
  const glm::dvec3 right(view[0][0], view[1][0], view[2][0]), up(view[0][1], view[1][1], view[2][1]);
  const double per_pixel = double(view_height(camera)) / double(std::max(1, height));
  camera.target += per_pixel * (-double(delta.x) * right + double(delta.y) * up);
}

void zoom_to_cursor(Camera& camera, float steps, int width, int height, glm::vec2 cursor,
                    std::optional<glm::dvec3> anchor) {
  const float scale = std::pow(0.85f, steps);
  const glm::dvec3 eye = camera.eye_double();
  if (!anchor) {  // the cursor's point at the target's depth
    const Ray ray = pixel_ray(camera, width, height, cursor);
    const glm::dvec3 forward = glm::normalize(camera.target - eye);
    const double t = glm::dot(camera.target - ray.origin, forward) / std::max(1e-6, glm::dot(ray.direction, forward));
    anchor = ray.origin + t * ray.direction;
  }
  // Eye and target both move toward the anchor by the same factor: the view direction is kept and
  // the anchor stays on the same pixel. Never closer than a millionth of the old distance.
  const float new_distance = std::max(camera.distance * scale, 1e-6f);
  const double s = double(new_distance) / double(camera.distance);
  camera.target = *anchor + (camera.target - *anchor) * s;
  camera.distance = new_distance;
}

Camera frame_points(const Camera& camera, const CovarianceMesh& mesh, const std::vector<int>& vertices,
                    double min_radius) {
  if (vertices.empty()) return camera;
  Vec3 lo = mesh.mean(size_t(vertices[0])), hi = lo;
  for (const int v : vertices) {
    lo = lo.cwiseMin(mesh.mean(size_t(v)));
    hi = hi.cwiseMax(mesh.mean(size_t(v)));
  }
  const Vec3 centre = 0.5 * (lo + hi), half = Vec3::Constant(min_radius / std::sqrt(3.0));
  Camera framed =
      frame_box(lo.cwiseMin(centre - half), hi.cwiseMax(centre + half), camera.yaw_degrees, camera.pitch_degrees);
  framed.fov_degrees = camera.fov_degrees;
  return framed;
}

Camera frame_points_in_region(const Camera& camera, const CovarianceMesh& mesh, const std::vector<int>& vertices,
                              double min_radius, glm::vec2 window, glm::vec2 region_min, glm::vec2 region_max) {
  if (vertices.empty()) return camera;
  std::vector<glm::dvec3> points;
  points.reserve(vertices.size() + 8);
  Vec3 lo = mesh.mean(size_t(vertices[0])), hi = lo;
  for (const int v : vertices) {
    const Vec3& p = mesh.mean(size_t(v));
    points.emplace_back(p.x(), p.y(), p.z());
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  if (min_radius > 0.0) {  // the corners of a cube of that circumradius around the points' centre
    const Vec3 centre = 0.5 * (lo + hi);
    const double half = min_radius / std::sqrt(3.0);
    for (int c = 0; c < 8; ++c)
      points.emplace_back(centre.x() + (c & 1 ? half : -half), centre.y() + (c & 2 ? half : -half),
                          centre.z() + (c & 4 ? half : -half));
  }
  const double aspect = double(window.x) / double(std::max(window.y, 1.0f));
  const NdcRect region = ndc_of_pixels(window, region_min, glm::max(region_max, region_min + 1.0f));
  return frame_silhouette(camera, points, aspect, region);
}

}  // namespace gps
