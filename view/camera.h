#pragma once
// An orbit camera: yaw and pitch around a target at a distance, perspective projection, with the
// world axis that shows upward chosen (y by default; scans often have z up).
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "core/mesh/linalg.h"

namespace gps {

struct Camera {
  glm::dvec3 target{0.0};  // double: a float target far from the origin would be off by more than the mesh
  float yaw_degrees = 30.0f;    // around the up axis
  float pitch_degrees = 20.0f;  // above the plane normal to it
  int up_axis = 1;              // the world axis drawn upward: 0 x, 1 y, 2 z
  float distance = 5.0f;
  float fov_degrees = 35.0f;
  bool orthographic = false;  // parallel projection showing the height the perspective shows at the target

  bool operator==(const Camera&) const = default;

  glm::vec3 eye() const { return glm::vec3(eye_double()); }
  glm::dvec3 eye_double() const;
  /// The eye's place relative to the target.
  glm::dvec3 eye_offset() const;
  glm::mat4 view() const { return glm::mat4(view_double()); }
  glm::mat4 projection(float aspect) const;
  glm::mat4 view_projection(float aspect) const { return projection(aspect) * view(); }
  /// view() and view_projection() in double, for combining with a model matrix before the cast to
  /// float (far from the origin, a float eye loses the view's direction).
  glm::dmat4 view_double() const;
  glm::dmat4 view_projection_double(float aspect) const;

private:
  /// The rotation from the y-up frame the angles are given in to the world: y to the up axis (z up:
  /// the yaw-0 eye looks from −y, as a front view of a z-up model does).
  glm::dmat3 up_frame() const;
};

/// The up axis named "x", "y" or "z"; throws a usage error otherwise.
int up_axis_named(const std::string& name);

/// The height of the view at the target's depth (world units).
float view_height(const Camera& camera);

/// A camera at the given angles that frames the box [lo, hi] (the whole box in view).
Camera frame_box(const Vec3& lo, const Vec3& hi, float yaw_degrees = 30.0f, float pitch_degrees = 20.0f);

/// frame_box() of the bounding box of a mesh's means.
Camera frame_mesh(const CovarianceMesh& mesh, float yaw_degrees = 30.0f, float pitch_degrees = 20.0f);
/// The camera a render asks for: {} frames the mesh from the default angles; {yaw, pitch} in degrees
/// frames it from there; a third value replaces the framed distance.
Camera frame_mesh(const CovarianceMesh& mesh, const std::vector<float>& yaw_pitch_distance);

}  // namespace gps
