#pragma once
// What the editor's viewport shows and how (the View panel edits it).
#include <map>
#include <string>

#include "render/pipeline/surface_renderer.h"
#include "ui/editing/mirror_modifier.h"
#include "ui/editing/snap_options.h"

namespace gps {

/// The target points drawn over the surface (View → Show target points…), each coloured by its
/// distance from it: what the View panel shows and edits while a target is loaded.
struct TargetPointsView {
  bool shown = true;
  float point_size = 5.0f;    // pixels
  bool automatic = true;      // the ramp ends at the distances' 99th percentile
  float max_distance = 0.0f;  // the ramp's red end (world units)
  // What the editor reports to the panel each frame.
  std::string name;                                      // the target's file name; "" while none is loaded
  size_t count = 0;                                      // its points
  bool measuring = false;                                // the distances shown are of an earlier surface
  double rms = 0.0, percentile_99 = 0.0, largest = 0.0;  // of the distances shown
  double length = 1.0;                                   // the points' bounding-box diagonal
};

struct ViewOptions {
  DrawOptions draw = [] {
    DrawOptions o;
    o.pixels = 6.0f;  // adaptive tessellation by default: ~6-pixel triangle edges at any zoom
    o.level = 8.0f;
    o.mesh_lines = true;
    o.ellipsoids = false;
    o.sigma_scale = 2.0f;
    o.background = {0.23f, 0.24f, 0.26f};
    return o;
  }();
  bool adaptive = true;  // draw.pixels is used (else draw.level)
  float adaptive_pixels = 6.0f;
  bool exact = true;            // Catmull-Clark extraordinary vertices evaluated exactly (else the thesis' plans)
  int depth = kExactPlanDepth;  // Catmull-Clark plan depth (rebuilds the plans when changed)
  int scheme = 0;               // 0 automatic (Loop for triangle meshes), 1 Loop, 2 Catmull-Clark
  bool warren = false;          // Loop with Warren's β (as Preiner's demo)
  bool triangle_mesh = false;   // the open mesh has only triangles: the panel offers the scheme (not kept)

  /// The plans these options ask for.
  PlanOptions plans() const {
    PlanOptions p;
    p.exact = exact;
    p.depth = depth;
    if (scheme == 1) p.scheme = Scheme::loop;
    if (scheme == 2) p.scheme = Scheme::catmull_clark;
    p.loop_beta = warren ? LoopBeta::warren : LoopBeta::loop;
    return p;
  }
  std::string matcap = "clay";
  bool vsync = true;
  bool common_frame = false;        // a multi-selection drag: every Gaussian in the grabbed one's frame (else its own)
  bool transform_gaussians = true;  // G / S / R carry the Gaussians (else they move the positions only)
  SnapOptions snap;                 // while transforming
  int transform_orientation = 0;    // the axes an axis key takes first in G / S / R: 0 Global, 1 Normal
  int pivot = 0;  // where the gizmo of a multi-selection sits: 0 the active vertex, 1 the selection's centroid
  int ellipsoid_scope =
      0;  // whose ellipsoids: 0 automatic (ui/overlays/ellipsoid_scope.h), 1 the selection and its neighbours, 2 all
  int up_axis = 1;  // the world axis drawn upward (0 x, 1 y, 2 z): the open file's, as kept in up_axes
  std::map<std::string, int> up_axes;                      // by mesh file (absolute path): the up axis last used for it
  std::map<std::string, MirrorSettings> mirror_modifiers;  // by mesh file (absolute path): its mirror modifier
  TargetPointsView target;
  std::map<std::string, std::string> target_files;  // by mesh file (absolute path): the target shown over it
  bool show_inspector = true, show_view = true, show_statistics = true, show_help = false;
};

}  // namespace gps
