#pragma once
// The handles drawn on a selected vertex's ellipsoid (issue "editor"): both ends of each principal
// axis and the centre. Hit-testing in window pixels, and the drag that turns cursor motion into a
// new Gaussian: along an axis scales it, across it rotates the frame, the centre moves the mean.
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "core/covariance_mesh.h"
#include "render/camera.h"
#include "ui/covariance_edit.h"

namespace gps {

/// What the viewport shows: camera and window size in window pixels (the mouse's units).
struct Viewport {
  Camera camera;
  int width = 1, height = 1;
};

/// One handle of one vertex: an axis end (axis 0..2 in ascending σ, side ±1) or the centre (axis −1).
struct Handle {
  int vertex = -1;
  int axis = -1;
  int side = 1;
  bool is_centre() const { return axis < 0; }
};

/// Where a vertex's handles sit: axis ends at k·σ_i from the mean, but never closer than
/// `min_pixels` on screen so that a needle-thin Gaussian can still be grabbed.
struct HandleFrame {
  Vec3 centre;
  EllipsoidAxes axes;
  Vec3 lengths;  // world distance from the centre to each axis end
  Vec3 end(int axis, int side) const { return centre + double(side) * lengths[axis] * axes.axes.col(axis); }
};

HandleFrame handle_frame(const CovarianceMesh& mesh, int vertex, double k_sigma, const Viewport& view, double min_pixels = 24.0);

/// The handle of `vertices` nearest to `pixel` within `radius` pixels (axis ends before the centre
/// when equally near, then the front-most); nullopt when none is that near.
std::optional<Handle> hit_handle(const Viewport& view, glm::vec2 pixel, const CovarianceMesh& mesh, const std::vector<int>& vertices,
                                 double k_sigma, float radius = 8.0f);

/// A handle drag in progress. The cursor moves on a plane through the grabbed point that contains
/// the axis and faces the camera (for the centre: faces the camera). For an axis end at distance r,
/// cursor motion d along the axis scales σ_axis by (r + d)/r (axis_drag_factor) and motion p across
/// it turns the frame by the rotation taking the axis to r·axis + p. Every selected vertex gets the
/// same relative change: its own axis of the same rank scaled, its frame turned by the same rotation,
/// its mean moved by the same vector; covariances stay SPD (clamp_spd).
class HandleDrag {
public:
  HandleDrag(const CovarianceMesh& mesh, const std::vector<int>& vertices, const Handle& grabbed, double k_sigma, const Viewport& view,
             glm::vec2 start_pixel);

  /// Writes the dragged Gaussians into `mesh` for the cursor at `pixel`; returns whether the
  /// cursor's ray met the drag plane (else `mesh` is left as it was).
  bool update(CovarianceMesh& mesh, const Viewport& view, glm::vec2 pixel) const;

  const std::vector<int>& vertices() const { return vertices_; }
  const Handle& handle() const { return handle_; }

private:
  std::optional<Vec3> plane_point(const Viewport& view, glm::vec2 pixel) const;

  std::vector<int> vertices_;
  std::vector<Vec3> means_;
  std::vector<Mat3> covariances_;
  Handle handle_;
  Vec3 axis_ = Vec3::UnitX();  // the grabbed axis end's direction (side included), unit
  double length_ = 1.0;        // the grabbed end's distance from the centre
  Vec3 plane_origin_, plane_normal_;
  Vec3 start_point_;
};

}  // namespace gps
