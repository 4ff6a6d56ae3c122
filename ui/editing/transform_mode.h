#pragma once
// Blender's modal transforms of the selected vertices: G grab, S scale, R rotate (about the view
// axis). The mouse sets the amount from where it was when the transform began; X, Y, Z constrain it
// to an axis and Shift+X, Y, Z to the plane normal to one; typed
// digits replace the mouse ("S 0.5", "G Z 1", "R 90" degrees). The axes are those of a transform
// orientation (ui/editing/transform_orientation.h): the first press of a key takes the default one,
// the second the other (Global ↔ Normal), the third removes the constraint, as Blender's. Each vertex
// is carried by an affine map about the pivot — μ′ = Aμ + t, Σ′ = AΣAᵀ
// (core/modelling/affine_transform.h) — weighted for proportional editing and mirrored for mirror
// editing.
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/modelling/affine_transform.h"
#include "ui/editing/edit_reach.h"
#include "ui/editing/transform_orientation.h"
#include "view/projection.h"

namespace gps {

class EditorDocument;

enum class TransformKind { grab, scale, rotate };

/// What a transform turns or scales about: the selection's median point (the mean of its means),
/// the active vertex, each vertex about its own mean (which changes only its covariance under S and
/// R), or the 3D cursor.
enum class TransformPivot { median, active, individual, cursor };
constexpr int kTransformPivots = 4;
/// "median point", "active vertex", "individual origins", "3D cursor".
const char* pivot_name(TransformPivot pivot);

class TransformMode {
public:
  /// Begins a transform of `vertices` (their Gaussians as in `mesh` now), with the mouse at `cursor`;
  /// `cursor_point`: the 3D cursor, the pivot of TransformPivot::cursor.
  TransformMode(TransformKind kind, const CovarianceMesh& mesh, std::vector<int> vertices, int active,
                TransformPivot pivot, const Viewport& view, glm::vec2 cursor, const Vec3& cursor_point = Vec3::Zero());

  /// The axes an axis key takes: `first` on its first press (Global: the world's), the other on the
  /// second; `normal_frame`: the Normal orientation's axes as columns (normal_frame()).
  void set_orientations(TransformOrientation first, const Mat3& normal_frame);
  /// X, Y, Z (axis 0, 1, 2): along the axis of the first orientation; `exclude`: in the plane normal
  /// to it. The same key again: the other orientation's axis; a third time: unconstrained.
  void constrain_axis(int axis, bool exclude);
  /// Along a unit direction (the normal of an extrusion).
  void constrain_direction(const Vec3& direction, const std::string& name);
  /// The typed amount: a distance (G), factor (S) or angle in degrees (R), NaN while none is valid,
  /// and its text as shown ("" follows the mouse).
  void set_typed(const std::string& text, double value) { typed_ = text, typed_value_ = value; }
  const std::string& typed() const { return typed_; }
  /// Follows the cursor (ignored while a value is typed).
  void move_cursor(glm::vec2 cursor, const Viewport& view);
  /// Increment snapping: rounds what the mouse set to whole steps — a move's world components (or its
  /// length along an axis or direction constraint), a scale factor, an angle in degrees.
  void snap_increment(double distance_step, double factor_step, double angle_step);
  /// Snapping to an element (a grab): the move takes the median or active pivot onto `point`, kept to
  /// the constraint (the point's projection onto the axis line or into the plane).
  void snap_to(const Vec3& point);
  /// The median or active pivot: where a grab's snapping takes it from.
  const Vec3& centre() const { return centre_; }

  TransformKind kind() const { return kind_; }
  const std::vector<int>& vertices() const { return vertices_; }
  /// The map of the vertex vertices()[source], at weight w ∈ [0, 1] (1: the full transform).
  AffineMap map(size_t source, double weight = 1.0) const;
  /// The pivot of vertices()[source].
  Vec3 pivot(size_t source) const;
  /// "Scale 0.5000 along y (median point)": for the status bar.
  std::string describe() const;

private:
  Vec3 axis_direction() const;  // the constraint's direction (axis or given); zero when none
  Mat3 frame() const;           // the axes of the orientation in use, as columns

  TransformKind kind_;
  std::vector<int> vertices_;
  std::vector<Vec3> start_means_;
  TransformPivot pivot_;
  Vec3 centre_ = Vec3::Zero();  // the median or active pivot
  glm::vec2 start_cursor_{0.0f};
  enum class Constraint { none, axis, plane, direction } constraint_ = Constraint::none;
  int axis_ = 0;
  TransformOrientation first_orientation_ = TransformOrientation::global, orientation_ = TransformOrientation::global;
  Mat3 normal_frame_ = Mat3::Identity();
  Vec3 direction_ = Vec3::Zero();
  std::string direction_name_;
  std::string typed_;
  double typed_value_ = std::numeric_limits<double>::quiet_NaN();
  // What the mouse set: a translation (G), a factor (S), an angle about an axis (R).
  Vec3 translation_ = Vec3::Zero();
  double factor_ = 1.0, angle_ = 0.0;
  Vec3 rotation_axis_ = Vec3::UnitZ();
  Vec3 view_axis_ = Vec3::UnitZ();  // from the pivot toward the eye
};

/// The map seen in the mirror across the plane x_axis = 0: x ↦ M f(M x).
AffineMap mirrored(const AffineMap& map, int axis);

/// Sets every reached vertex to its start Gaussian carried by its source's map at its weight
/// (mirrored across `mirror_axis` where it is the mirror image) through carried_gaussian, as
/// transform_vertices carries them; with `carry_gaussians` false, or a map that only moves, the
/// covariance stays as it started. Returns how many covariances were held at the flatness floor.
size_t apply_transform(EditorDocument& document, const TransformMode& transform,
                       const std::vector<ReachedVertex>& reach, int mirror_axis, bool carry_gaussians);

}  // namespace gps
