#pragma once
// Snapping while transforming, as Blender's: what it aims at and the steps of increment snapping.
// It is on while the option is set, and held Ctrl inverts it for as long as it is held.
#include "view/snap_point.h"

namespace gps {

struct SnapOptions {
  bool enabled = false;
  SnapTarget target = SnapTarget::increment;
  double distance_step = 0.1;  // G: world units per step (along each axis, or along the constraint)
  double factor_step = 0.1;    // S
  double angle_step = 5.0;     // R: degrees

  /// Whether a transform snaps now, with Ctrl held or not.
  bool active(bool ctrl) const { return enabled != ctrl; }
};

}  // namespace gps
