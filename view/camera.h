#pragma once
// An orbit camera: yaw and pitch around a target at a distance, perspective projection.
#include <glm/glm.hpp>
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "core/mesh/linalg.h"

namespace gps {

struct Camera {
  glm::vec3 target{0.0f};
  float yaw_degrees = 30.0f;    // around +y
  float pitch_degrees = 20.0f;  // above the xz-plane
  float distance = 5.0f;
  float fov_degrees = 35.0f;
  bool orthographic = false;  // parallel projection showing the height the perspective shows at the target

  glm::vec3 eye() const;
  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;
  glm::mat4 view_projection(float aspect) const { return projection(aspect) * view(); }
  /// view() and view_projection() in double, for combining with a model matrix before the cast to
  /// float (far from the origin, a float eye loses the view's direction).
  glm::dmat4 view_double() const;
  glm::dmat4 view_projection_double(float aspect) const;
};

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
