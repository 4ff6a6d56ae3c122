#pragma once
// `gpsurf bench --edit`: edit-to-frame time on a large mesh. A current GL context needed.
#include <nlohmann/json.hpp>
#include <string>

#include "core/plans/planned_surface.h"

namespace gps {

/// On sample `name` at `faces` faces (bench/edit_scene.h): an edit maps only the changed vertices to
/// 9D and re-applies the stencils that read them (no topology rebuild), against the plain frame, the
/// full recompute and set_mesh. Wall times to after glFinish, measured interleaved.
nlohmann::json edit_figures(const std::string& name, int faces, const PlanOptions& options);

}  // namespace gps
