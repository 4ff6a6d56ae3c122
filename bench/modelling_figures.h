#pragma once
// `gpsurf bench --model`: operation-to-frame time of the modelling operations on a large mesh: the
// operation (core/modelling/), the incremental re-plan of the new topology beside a full one, the
// upload, and the frame that shows it. A current GL context needed.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/plans/planned_surface.h"

namespace gps {

/// The operations modelling_figures times, by the names its rows give them, in its order.
const std::vector<std::string>& modelling_operations();

/// The operations `words` name, each the first words of one or more of modelling_operations() ("loop"
/// or "loop cut": "loop cut"), in that order and each once. Throws gps::Error naming a word that
/// names none.
std::vector<std::string> modelling_operations_named(const std::vector<std::string>& words);

/// On sample `name` at `faces` faces in a 1280×720 frame at adaptive 6-pixel edges: each operation
/// applied to the same mesh, median wall times of its phases (each to after glFinish) and in total. An
/// operation the mesh refuses, or one that changes its scheme, has only "skipped": why.
/// `crease_every` > 0: every such edge (by index) creased at sharpness 2 first, as a designer's
/// creases give the tables many stencil rows. `only`, where not empty: those operations alone (names
/// from modelling_operations()).
nlohmann::json modelling_figures(const std::string& name, int faces, const PlanOptions& options, int crease_every = 0,
                                 const std::vector<std::string>& only = {});

}  // namespace gps
