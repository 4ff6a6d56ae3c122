#pragma once
// `gpsurf bench --model`: operation-to-frame time of the modelling operations on a large mesh: the
// operation (core/modelling/), the incremental re-plan of the new topology beside a full one, the
// upload, and the frame that shows it. A current GL context needed.
#include <nlohmann/json.hpp>
#include <string>

#include "core/plans/planned_surface.h"

namespace gps {

/// On sample `name` at `faces` faces in a 1280×720 frame at adaptive 6-pixel edges: each operation
/// applied to the same mesh, median wall times of its phases (each to after glFinish) and in total. An
/// operation the mesh refuses, or one that changes its scheme, has only "skipped": why.
/// `crease_every` > 0: every such edge (by index) creased at sharpness 2 first, as a designer's
/// creases give the tables many stencil rows.
nlohmann::json modelling_figures(const std::string& name, int faces, const PlanOptions& options, int crease_every = 0);

}  // namespace gps
