#pragma once
// The inspector: the active vertex's mean, its covariance as three standard deviations and an
// orientation, and presets. Every change applies to all selected vertices as the same relative
// change, and is one undo step (one per preset, one per numeric entry).
#include <optional>
#include <vector>

#include "ui/edit_history.h"
#include "ui/editor_document.h"
#include "ui/selection.h"

namespace gps {

class InspectorPanel {
public:
  /// Draws the panel (between ImGui::NewFrame and ImGui::Render); returns the vertices it changed.
  std::vector<int> draw(EditorDocument& document, const Selection& selection, bool* open);

private:
  std::vector<int> apply_preset(EditorDocument& document, const Selection& selection, int preset);

  std::optional<VertexEdit> entry_;  // a numeric entry in progress: committed when its field is left
  double isotropic_sigma_ = 0.05;
};

/// Euler angles (degrees, rotations about x then y then z: R = Rz·Ry·Rx) of a rotation matrix.
Vec3 euler_degrees(const Mat3& rotation);
/// The rotation matrix of euler_degrees().
Mat3 rotation_from_euler_degrees(const Vec3& angles);

}  // namespace gps
