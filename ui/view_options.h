#pragma once
// What the editor's viewport shows and how (the View panel edits it).
#include <string>

#include "render/surface_renderer.h"

namespace gps {

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
  bool adaptive = true;       // draw.pixels is used (else draw.level)
  float adaptive_pixels = 6.0f;
  int depth = 3;              // maximum plan depth (rebuilds the plans when changed)
  std::string matcap = "clay";
  bool vsync = true;
  bool common_frame = false;  // a multi-selection drag: every Gaussian in the grabbed one's frame (else its own)
  bool show_inspector = true, show_view = true, show_statistics = true, show_help = false;
};

}  // namespace gps
