#pragma once
// The gizmo on the active vertex's ellipsoid (or its axes at a pivot, such as the selection's
// centroid): both ends of each principal axis and the centre.
// Hit-testing in window pixels, and the drag that turns cursor motion into one kind of change:
// an axis end dragged along its axis scales that σ (the frame kept), across it turns the frame
// (every σ kept), with Shift all three σ scale together; the centre moves the mean in the view
// plane, along one axis, in one plane or along the surface normal, by the mouse or a typed distance.
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/edit/covariance_edit.h"
#include "core/mesh/covariance_mesh.h"
#include "core/edit/gaussian_change.h"
#include "view/projection.h"

namespace gps {

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

HandleFrame handle_frame(const CovarianceMesh& mesh, int vertex, double k_sigma, const Viewport& view,
                         double min_pixels = 24.0);
HandleFrame handle_frame(const Vec3& centre, const EllipsoidAxes& axes, double k_sigma, const Viewport& view,
                         double min_pixels = 24.0);

/// The handle of `vertices` nearest to `pixel` within `radius` pixels (axis ends before the centre
/// when equally near, then the front-most); nullopt when none is that near.
std::optional<Handle> hit_handle(const Viewport& view, glm::vec2 pixel, const CovarianceMesh& mesh,
                                 const std::vector<int>& vertices, double k_sigma, float radius = 8.0f);
/// The same for one gizmo, `frame`, that edits `vertex` (and the selection with it) wherever it sits.
std::optional<Handle> hit_handle(const Viewport& view, glm::vec2 pixel, const HandleFrame& frame, int vertex,
                                 float radius = 8.0f);

/// How the centre handle moves the mean: in the view plane, along a world axis (X/Y/Z), in the
/// plane normal to one (Shift+X/Y/Z), or along the surface normal at the vertex (N).
enum class MoveConstraint { view_plane, axis, plane, normal };

/// What the keyboard adds to a drag.
struct DragModifiers {
  bool uniform = false;  // an axis end scales all three σ (Shift)
  bool snap = false;     // σ ratios in steps of 0.1, angles in steps of 5°, distances of 0.1·σ (Ctrl)
};

/// A handle drag in progress. The cursor moves on a plane through the grabbed point that contains
/// the axis and faces the camera (for the centre: faces the camera). For an axis end at distance r,
/// cursor motion d along the axis scales σ_axis by (r + d)/r (axis_drag_factor); motion p across it
/// turns the frame by the rotation taking the axis to r·axis + p. The first few pixels of motion
/// decide which of the two the drag does. Every selected vertex gets the same relative change: its
/// own axis of the same rank scaled (or, in a common frame, the grabbed vertex's axis), its frame
/// turned by the same rotation, its mean moved by the same vector. `pivot` places the gizmo (the
/// grabbed vertex's axes) elsewhere than on the grabbed vertex's mean; the change stays the same.
class HandleDrag {
public:
  enum class Kind { undecided, scale, rotate, move };

  HandleDrag(const CovarianceMesh& mesh, const std::vector<int>& vertices, const Handle& grabbed, double k_sigma,
             const Viewport& view, glm::vec2 start_pixel, bool common_frame = false,
             const std::optional<Vec3>& pivot = std::nullopt);

  /// The change of each of vertices() for the cursor at `pixel` (applied to their values at the
  /// start of the drag); nullopt when the cursor's ray misses the drag plane.
  std::optional<std::vector<GaussianChange>> update(const Viewport& view, glm::vec2 pixel,
                                                    const DragModifiers& modifiers = {});

  /// Constrains a centre drag (axis: 0..2 for X/Y/Z, ignored for view_plane and normal).
  void constrain(MoveConstraint constraint, int axis = 0);
  /// A typed distance for a constrained centre move ("" for none): replaces the mouse's.
  void set_typed(const std::string& text) { typed_ = text; }
  const std::string& typed() const { return typed_; }

  const std::vector<int>& vertices() const { return vertices_; }
  const Handle& handle() const { return handle_; }
  Kind kind() const { return kind_; }
  /// The grabbed vertex's frame now: its start axes with the change applied, each axis keeping its
  /// index (and so its colour) for the whole drag.
  HandleFrame frame(const Viewport& view) const;
  /// Where the grabbed vertex's mean was when the drag began.
  const Vec3& start_centre() const { return grabbed_mean_; }
  /// A one-line description for the status bar ("scale σ1 ×1.25", "move along z 0.3").
  std::string describe() const;

private:
  std::optional<Vec3> plane_point(const Viewport& view, glm::vec2 pixel) const;
  std::optional<Vec3> move_motion(const Viewport& view, glm::vec2 pixel, bool snap) const;
  GaussianChange change_for(size_t i) const;

  std::vector<int> vertices_;
  std::vector<EllipsoidAxes> start_axes_;
  Handle handle_;
  size_t grabbed_index_ = 0;
  bool common_frame_ = false;
  double k_sigma_ = 2.0;
  Vec3 centre_ = Vec3::Zero(),
       normal_ = Vec3::UnitZ();  // the gizmo's centre at the start (the pivot), the grabbed vertex's normal
  Vec3 grabbed_mean_ = Vec3::Zero();
  Vec3 axis_ = Vec3::UnitX();  // the grabbed axis end's direction (side included), unit
  double length_ = 1.0;        // the grabbed end's distance from the centre
  double sigma_ = 1.0;         // the grabbed Gaussian's largest σ (snapping step for distances)
  Vec3 plane_origin_, plane_normal_;
  Vec3 start_point_;
  glm::vec2 start_pixel_{0.0f};
  Kind kind_ = Kind::undecided;
  MoveConstraint constraint_ = MoveConstraint::view_plane;
  int constraint_axis_ = 0;
  std::string typed_;
  GaussianChange change_;  // of the grabbed vertex
};

}  // namespace gps
