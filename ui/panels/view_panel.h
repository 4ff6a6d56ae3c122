#pragma once
// The View panel: tessellation (uniform level or adaptive pixel size), plan depth, MatCap, shading,
// the up axis, overlays (base mesh, ellipsoids and their k-sigma scale, tessellation wireframe), and
// while a target is loaded its points' distance ramp (a legend and its maximum) and point size.
#include "ui/panels/view_options.h"

namespace gps {

struct ViewPanelChanges {
  bool depth = false;        // the plans must be rebuilt
  bool matcap = false;       // options.matcap names another built-in
  bool load_matcap = false;  // the user asked to load a MatCap image
  bool up_axis = false;      // options.up_axis changed: the view turns and frames the mesh again
  bool target_shown = false;  // options.target.shown was toggled
};

ViewPanelChanges draw_view_panel(ViewOptions& options, bool* open);

}  // namespace gps
