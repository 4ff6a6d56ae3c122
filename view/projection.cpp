#include "view/projection.h"

#include <algorithm>
#include <cmath>

namespace gps {

namespace {

glm::dvec2 pixel_to_ndc(int width, int height, glm::vec2 pixel) {
  return {2.0 * double(pixel.x) / double(width) - 1.0, 1.0 - 2.0 * double(pixel.y) / double(height)};
}

}  // namespace

Ray pixel_ray(const Camera& camera, int width, int height, glm::vec2 pixel) {
  const glm::dvec2 ndc = pixel_to_ndc(width, height, pixel + glm::vec2(0.5f));
  const glm::dmat4 inverse = glm::inverse(camera.view_projection_double(float(width) / float(height)));
  const glm::dvec4 near_point = inverse * glm::dvec4(ndc, -1.0, 1.0), far_point = inverse * glm::dvec4(ndc, 1.0, 1.0);
  const glm::dvec3 a = glm::dvec3(near_point) / near_point.w, b = glm::dvec3(far_point) / far_point.w;
  // Perspective rays leave the eye; parallel ones leave the near plane.
  return {camera.orthographic ? a : camera.eye_double(), glm::normalize(b - a)};
}

std::optional<glm::vec3> project_to_pixel(const Camera& camera, int width, int height, const Vec3& world) {
  const glm::dvec4 clip =
      camera.view_projection_double(float(width) / float(height)) * glm::dvec4(world.x(), world.y(), world.z(), 1.0);
  if (clip.w <= 0.0) return std::nullopt;
  const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
  return glm::vec3(float((ndc.x + 1.0) * 0.5 * double(width)), float((1.0 - ndc.y) * 0.5 * double(height)),
                   float(ndc.z));
}

std::optional<glm::vec3> visible_pixel(const Camera& camera, int width, int height, const Vec3& world) {
  const auto p = project_to_pixel(camera, width, height, world);
  if (!p || p->z < -1.0f || p->z > 1.0f) return std::nullopt;
  return p;
}

double world_per_pixel(const Camera& camera, int height, const Vec3& point) {
  if (camera.orthographic) return double(view_height(camera)) / double(std::max(1, height));
  const Vec3 eye = to_vec(camera.eye_double());
  const Vec3 forward = (to_vec(camera.target) - eye).normalized();
  const double depth = std::max(1e-9, (point - eye).dot(forward));
  return 2.0 * depth * std::tan(glm::radians(double(camera.fov_degrees)) * 0.5) / double(std::max(1, height));
}

NearestProjected::NearestProjected(const Camera& camera, int width, int height, glm::vec2 pixel, float radius,
                                   float tolerance)
    : camera_(camera),
      width_(width),
      height_(height),
      centre_(pixel + glm::vec2(0.5f)),
      radius_(radius),
      tolerance_(tolerance),
      best_distance_(radius) {}

void NearestProjected::consider(int id, const Vec3& point, int priority) {
  const auto p = visible_pixel(camera_, width_, height_, point);
  if (!p) return;
  const float distance = glm::length(glm::vec2(*p) - centre_);
  if (distance > radius_) return;
  const bool nearer = distance < best_distance_ - tolerance_;
  const bool as_near = distance <= best_distance_ + tolerance_;
  const bool wins_tie = priority > best_priority_ || (priority == best_priority_ && p->z < best_depth_);
  if (best_ < 0 || nearer || (as_near && wins_tie)) {
    best_ = id;
    best_priority_ = priority;
    best_distance_ = distance;
    best_depth_ = p->z;
  }
}

}  // namespace gps
