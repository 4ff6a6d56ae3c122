#include "view/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/support/error.h"

namespace gps {

glm::dmat3 Camera::up_frame() const {
  // Columns: the images of the y-up frame's x, y and z; each a proper rotation.
  if (up_axis == 2) return glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, -1, 0));
  if (up_axis == 0) return glm::dmat3(glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0));
  return glm::dmat3(1.0);
}

int up_axis_named(const std::string& name) {
  if (name == "x") return 0;
  if (name == "y") return 1;
  if (name == "z") return 2;
  throw usage_error("up axis must be x, y or z, not \"" + name + "\"");
}

// The near plane follows the distance at any scale (a fixed floor would clip a tiny mesh).
glm::mat4 Camera::projection(float aspect) const {
  const float near_plane = distance > 0.0f ? distance * 0.01f : 1e-4f, far_plane = distance * 100.0f;
  if (orthographic) {
    const float half = 0.5f * view_height(*this);
    return glm::ortho(-half * aspect, half * aspect, -half, half, near_plane, far_plane);
  }
  return glm::perspective(glm::radians(fov_degrees), aspect, near_plane, far_plane);
}

glm::dvec3 Camera::eye_offset() const {
  const double yaw = glm::radians(double(yaw_degrees)), pitch = glm::radians(double(pitch_degrees));
  return double(distance) *
         (up_frame() * glm::dvec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)));
}

glm::dvec3 Camera::eye_double() const { return target + eye_offset(); }

// Looking from the eye's offset at the origin, then moved to the target: eye − target would lose the
// offset's small components against a target far from the origin, and a view straight along the up
// axis (pitch ±90°) would have no sideways axis left.
glm::dmat4 Camera::view_double() const {
  return glm::lookAt(eye_offset(), glm::dvec3(0.0), up_frame() * glm::dvec3(0, 1, 0)) *
         glm::translate(glm::dmat4(1.0), -target);
}

glm::dmat4 Camera::view_projection_double(float aspect) const {
  const double d = double(distance);
  const double near_plane = d > 0.0 ? d * 0.01 : 1e-4, far_plane = d * 100.0;
  glm::dmat4 projection_d;
  if (orthographic) {
    const double half = d * std::tan(glm::radians(double(fov_degrees)) * 0.5);
    projection_d = glm::ortho(-half * aspect, half * aspect, -half, half, near_plane, far_plane);
  } else {
    projection_d = glm::perspective(glm::radians(double(fov_degrees)), double(aspect), near_plane, far_plane);
  }
  return projection_d * view_double();
}

float view_height(const Camera& camera) {
  return 2.0f * camera.distance * std::tan(glm::radians(camera.fov_degrees) * 0.5f);
}

Camera frame_box(const Vec3& lo, const Vec3& hi, float yaw_degrees, float pitch_degrees) {
  Camera c;
  const Vec3 centre = 0.5 * (lo + hi);
  c.target = glm::dvec3(centre.x(), centre.y(), centre.z());
  const float radius = std::max(1e-6f, float(0.5 * (hi - lo).norm()));
  c.yaw_degrees = yaw_degrees;
  c.pitch_degrees = pitch_degrees;
  c.distance = radius / std::sin(glm::radians(c.fov_degrees) * 0.5f) * 1.05f;
  return c;
}

Camera frame_mesh(const CovarianceMesh& mesh, float yaw_degrees, float pitch_degrees) {
  Vec3 lo, hi;
  bounding_box(mesh, lo, hi);
  return frame_box(lo, hi, yaw_degrees, pitch_degrees);
}

Camera frame_mesh(const CovarianceMesh& mesh, const std::vector<float>& yaw_pitch_distance) {
  if (yaw_pitch_distance.size() < 2) return frame_mesh(mesh);
  Camera camera = frame_mesh(mesh, yaw_pitch_distance[0], yaw_pitch_distance[1]);
  if (yaw_pitch_distance.size() > 2) camera.distance = yaw_pitch_distance[2];
  return camera;
}

}  // namespace gps
