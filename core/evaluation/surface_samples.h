#pragma once
// A planned surface evaluated where its mesh lies: its points are about its evaluation origin
// (core/plans/planned_surface.h), and what they evaluate to is moved back by it here.
#include <optional>

#include "core/evaluation/patch_eval.h"
#include "core/evaluation/tessellator.h"
#include "core/plans/planned_surface.h"

namespace gps {

/// tessellate() of the surface's plans and points, the positions moved back to the mesh's place.
TriangleMesh tessellate(const PlannedSurface& surface, int level, const ProgressReport& progress = {});

/// evaluate_patch() of the surface at (u, v) of a patch, the position moved back to the mesh's place.
std::optional<PatchSample> evaluate_patch(const PlannedSurface& surface, int patch, double u, double v);

}  // namespace gps
