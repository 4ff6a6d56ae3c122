#include "ui/axis_handles.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "render/picking.h"

namespace gps {

namespace {

glm::vec3 to_glm(const Vec3& v) { return {float(v.x()), float(v.y()), float(v.z())}; }
Vec3 to_vec(const glm::vec3& v) { return {double(v.x), double(v.y), double(v.z)}; }

Vec3 eye_of(const Viewport& view) { return to_vec(view.camera.eye()); }

// World length of one window pixel at the depth of `point` (perspective: 2·z·tan(fov/2)/height).
double world_per_pixel(const Viewport& view, const Vec3& point) {
  const Vec3 forward = (to_vec(view.camera.target) - eye_of(view)).normalized();
  const double depth = std::max(1e-9, (point - eye_of(view)).dot(forward));
  return 2.0 * depth * std::tan(glm::radians(double(view.camera.fov_degrees)) * 0.5) / double(view.height);
}

}  // namespace

HandleFrame handle_frame(const CovarianceMesh& mesh, int vertex, double k_sigma, const Viewport& view, double min_pixels) {
  HandleFrame f;
  f.centre = mesh.mean(size_t(vertex));
  f.axes = ellipsoid_axes(mesh.covariance(size_t(vertex)));
  const double floor_length = min_pixels * world_per_pixel(view, f.centre);
  for (int a = 0; a < 3; ++a) f.lengths[a] = std::max(k_sigma * f.axes.sigmas[a], floor_length);
  return f;
}

std::optional<Handle> hit_handle(const Viewport& view, glm::vec2 pixel, const CovarianceMesh& mesh, const std::vector<int>& vertices,
                                 double k_sigma, float radius) {
  const glm::vec2 cursor = pixel + glm::vec2(0.5f);
  std::optional<Handle> best;
  float best_distance = radius, best_depth = 2.0f;
  const auto consider = [&](const Handle& h, const Vec3& point) {
    const auto p = project_to_pixel(view.camera, view.width, view.height, to_glm(point));
    if (!p || p->z < -1.0f || p->z > 1.0f) return;
    const float distance = glm::length(glm::vec2(*p) - cursor);
    if (distance > radius) return;
    // Ends win over a centre as near (within a pixel): they overlap it when the axes are short.
    const bool nearer = distance < best_distance - 1.0f;
    const bool as_near = distance <= best_distance + 1.0f;
    const bool preferred = best && best->is_centre() && !h.is_centre();
    if (!best || nearer || (as_near && (preferred || (best->is_centre() == h.is_centre() && p->z < best_depth)))) {
      best = h;
      best_distance = distance;
      best_depth = p->z;
    }
  };
  for (const int v : vertices) {
    const HandleFrame f = handle_frame(mesh, v, k_sigma, view);
    for (int axis = 0; axis < 3; ++axis)
      for (const int side : {1, -1}) consider(Handle{v, axis, side}, f.end(axis, side));
    consider(Handle{v, -1, 1}, f.centre);
  }
  return best;
}

HandleDrag::HandleDrag(const CovarianceMesh& mesh, const std::vector<int>& vertices, const Handle& grabbed, double k_sigma,
                       const Viewport& view, glm::vec2 start_pixel)
    : vertices_(vertices), handle_(grabbed) {
  for (const int v : vertices_) {
    means_.push_back(mesh.mean(size_t(v)));
    covariances_.push_back(mesh.covariance(size_t(v)));
  }
  const HandleFrame f = handle_frame(mesh, grabbed.vertex, k_sigma, view);
  const Vec3 eye = eye_of(view);
  if (grabbed.is_centre()) {
    plane_origin_ = f.centre;
    plane_normal_ = (eye - f.centre).normalized();
  } else {
    axis_ = double(grabbed.side) * f.axes.axes.col(grabbed.axis);
    length_ = f.lengths[grabbed.axis];
    plane_origin_ = f.end(grabbed.axis, grabbed.side);
    // The plane containing the axis that faces the camera most: normal = view direction minus its
    // component along the axis; an axis pointing at the eye falls back to the camera-facing plane.
    const Vec3 to_eye = (eye - plane_origin_).normalized();
    const Vec3 n = to_eye - to_eye.dot(axis_) * axis_;
    plane_normal_ = n.norm() > 1e-3 ? n.normalized() : to_eye;
  }
  start_point_ = plane_point(view, start_pixel).value_or(plane_origin_);
}

std::optional<Vec3> HandleDrag::plane_point(const Viewport& view, glm::vec2 pixel) const {
  const Ray ray = pixel_ray(view.camera, view.width, view.height, pixel);
  const Vec3 origin = to_vec(ray.origin), direction = to_vec(ray.direction);
  const double facing = direction.dot(plane_normal_);
  if (std::abs(facing) < 1e-9) return std::nullopt;
  const double t = (plane_origin_ - origin).dot(plane_normal_) / facing;
  if (!(t > 0) || !std::isfinite(t)) return std::nullopt;
  return origin + t * direction;
}

bool HandleDrag::update(CovarianceMesh& mesh, const Viewport& view, glm::vec2 pixel) const {
  const auto point = plane_point(view, pixel);
  if (!point) return false;
  const Vec3 motion = *point - start_point_;
  if (handle_.is_centre()) {
    for (size_t i = 0; i < vertices_.size(); ++i) mesh.set_mean(size_t(vertices_[i]), means_[i] + motion);
    return true;
  }
  const double along = motion.dot(axis_);
  const Vec3 across = motion - along * axis_;
  const double factor = axis_drag_factor(length_, along);
  const Mat3 rotation = Eigen::Quaterniond::FromTwoVectors(axis_, length_ * axis_ + across).toRotationMatrix();
  for (size_t i = 0; i < vertices_.size(); ++i) {
    const Mat3 edited = rotate_covariance(scale_axis(covariances_[i], handle_.axis, factor), rotation);
    mesh.covariances[size_t(vertices_[i])] = clamp_spd(edited, covariances_[i]);
  }
  return true;
}

}  // namespace gps
