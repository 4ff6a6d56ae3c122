#pragma once
// `gpsurf bench --render`: frame times of one sample mesh per tessellation level (a current GL context needed).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/planned_surface.h"

namespace gps {

/// One row per level in a `size`×`size` target: the compute passes, the tessellated draw (live: every
/// patch evaluated), the surface cache's frame (stored triangles) and a frame after a one-vertex edit
/// (the cache captures again), and the floor: the same triangles (CPU tessellation) drawn from a
/// static vertex buffer with the same shading.
nlohmann::json frame_figures(const std::string& name, int faces, const PlanOptions& options, int size, const std::vector<int>& levels);

}  // namespace gps
