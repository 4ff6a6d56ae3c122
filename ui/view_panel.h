#pragma once
// The View panel: tessellation (uniform level or adaptive pixel size), plan depth, MatCap, shading,
// overlays (base mesh, ellipsoids and their k-sigma scale, tessellation wireframe).
#include "ui/view_options.h"

namespace gps {

struct ViewPanelChanges {
  bool depth = false;        // the plans must be rebuilt
  bool matcap = false;       // options.matcap names another built-in
  bool load_matcap = false;  // the user asked to load a MatCap image
};

ViewPanelChanges draw_view_panel(ViewOptions& options, bool* open);

}  // namespace gps
