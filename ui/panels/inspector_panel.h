#pragma once
// The inspector: the selection's means, standard deviations (per principal axis, coloured as the
// gizmo's axes) and orientation, presets, and how far edits reach (proportional, mirror). Values
// that differ across the selection show as "mixed"; a typed value applies to every selected vertex.
// Fields show rounded values of a fixed width; a field being edited holds the full-precision value.
// Every change is one undo step (one per preset, one per numeric entry); with mirror editing on, the
// mirror image of each selected vertex takes the mirrored change, as in a drag. The panel also says
// what the last modelling operation did or why it was refused, and the sharpness of the selected
// edges (crease) and vertices (corner), which the editor applies as a modelling step.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/edit/covariance_edit.h"
#include "ui/editing/edit_reach.h"
#include "ui/document/editor_document.h"
#include "ui/editing/selection.h"

namespace gps {

class InspectorPanel {
public:
  /// Draws the panel (between ImGui::NewFrame and ImGui::Render); edits go through the document.
  void draw(EditorDocument& document, const Selection& selection, ReachOptions& reach, bool* open);
  /// A sharpness the user entered for the selected edges (corners: the selected vertices' corner
  /// sharpness) once the entry is finished, which the editor applies as one undo step; taken once.
  struct SharpnessRequest {
    bool corners = false;
    double sharpness = 0.0;
  };
  std::optional<SharpnessRequest> take_sharpness_request() { return std::exchange(sharpness_request_, std::nullopt); }
  /// What the last modelling operation did (or, `error`, why it was refused), shown at the top.
  void set_note(const std::string& note, bool error) { note_ = note, note_error_ = error; }

private:
  void draw_means(EditorDocument& document, const std::vector<int>& vertices);
  void draw_sigmas(EditorDocument& document, const std::vector<int>& vertices, int active);
  void draw_rotation(EditorDocument& document, const std::vector<int>& vertices, int active);
  void draw_presets(EditorDocument& document, const std::vector<int>& vertices);
  void draw_sharpness(const EditorDocument& document, const Selection& selection);
  void sharpness_field(const char* label, double value, bool corners);
  void track_entry(EditorDocument& document);
  void mirror_change(EditorDocument& document, const std::vector<int>& vertices) const;
  std::optional<double> number_field(const char* label, double value, bool mixed, int decimals, float width);

  bool entry_open_ = false;                  // a numeric entry in progress: committed when its field is left
  std::optional<EllipsoidAxes> entry_axes_;  // the active vertex's axes when the entry began: fields keep their order
  double isotropic_sigma_ = 0.05;
  unsigned precise_id_ = 0;   // the field being edited (its ImGui id), which holds the full-precision value
  std::string precise_text_;  // that value's text as the entry began
  ReachOptions reach_;        // as drawn: whether a change is mirrored, and across which plane
  std::string note_;
  bool note_error_ = false;
  std::optional<double> sharpness_typed_;  // the sharpness field's text while it is being edited
  std::optional<SharpnessRequest> sharpness_request_;
};

/// Euler angles (degrees, rotations about x then y then z: R = Rz·Ry·Rx) of a rotation matrix.
Vec3 euler_degrees(const Mat3& rotation);
/// The rotation matrix of euler_degrees().
Mat3 rotation_from_euler_degrees(const Vec3& angles);

/// A value for a fixed-width display: rounded to `decimals`, without a negative zero.
double display_value(double value, int decimals);

}  // namespace gps
