#pragma once
// `gpsurf bench --render`: frame times of one sample mesh per tessellation level (a current GL context needed).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/plans/planned_surface.h"

namespace gps {

/// One row per uniform level, and one for adaptive levels of `adaptive_pixels` (0: none), in a
/// `size`×`size` target: the compute passes, the tessellated draw (live: every patch evaluated),
/// the surface cache's frame (stored triangles), a frame after a one-vertex edit (the cache
/// refreshes that vertex's patches), and the floor: the cached triangles, welded, drawn from a
/// static indexed vertex buffer with the same shading. JSON "level" is 0 for the adaptive row.
nlohmann::json frame_figures(const std::string& name, int faces, const PlanOptions& options, int size,
                             const std::vector<int>& levels, float adaptive_pixels);

}  // namespace gps
