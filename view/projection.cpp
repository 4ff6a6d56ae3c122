#include "view/projection.h"

#include <algorithm>
#include <cmath>

namespace gps {

namespace {

glm::vec2 pixel_to_ndc(int width, int height, glm::vec2 pixel) {
  return {2.0f * pixel.x / float(width) - 1.0f, 1.0f - 2.0f * pixel.y / float(height)};
}

}  // namespace

Ray pixel_ray(const Camera& camera, int width, int height, glm::vec2 pixel) {
  const glm::vec2 ndc = pixel_to_ndc(width, height, pixel + glm::vec2(0.5f));
  const glm::mat4 inverse = glm::inverse(camera.view_projection(float(width) / float(height)));
  const glm::vec4 near_point = inverse * glm::vec4(ndc, -1.0f, 1.0f), far_point = inverse * glm::vec4(ndc, 1.0f, 1.0f);
  const glm::vec3 a = glm::vec3(near_point) / near_point.w, b = glm::vec3(far_point) / far_point.w;
  // Perspective rays leave the eye; parallel ones leave the near plane.
  return {camera.orthographic ? a : camera.eye(), glm::normalize(b - a)};
}

std::optional<glm::vec3> project_to_pixel(const Camera& camera, int width, int height, const glm::vec3& world) {
  const glm::vec4 clip = camera.view_projection(float(width) / float(height)) * glm::vec4(world, 1.0f);
  if (clip.w <= 0.0f) return std::nullopt;
  const glm::vec3 ndc = glm::vec3(clip) / clip.w;
  return glm::vec3((ndc.x + 1.0f) * 0.5f * float(width), (1.0f - ndc.y) * 0.5f * float(height), ndc.z);
}

std::optional<glm::vec3> visible_pixel(const Camera& camera, int width, int height, const Vec3& world) {
  const auto p = project_to_pixel(camera, width, height, to_glm(world));
  if (!p || p->z < -1.0f || p->z > 1.0f) return std::nullopt;
  return p;
}

double world_per_pixel(const Camera& camera, int height, const Vec3& point) {
  if (camera.orthographic) return double(view_height(camera)) / double(std::max(1, height));
  const Vec3 eye = to_vec(camera.eye());
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
