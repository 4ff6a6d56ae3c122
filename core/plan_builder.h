#pragma once
// Subdivision plans and their stencil table from a mesh's topology (thesis 2.3, DESIGN.md §2).
#include "core/mesh_connectivity.h"
#include "core/plan_table.h"

namespace gps {

struct PlanTables {
  PlanTable plans;
  StencilTable stencils;
};

/// Builds one plan per patch (core/patch_layout.h numbering): quadtrees refined around
/// extraordinary and irregular boundary vertices down to `max_depth` (1..8), regular nodes as
/// bicubic B-splines (boundary phantoms p₋₁ = 2p₀ − p₁), terminal nodes as Bézier patches from the
/// rules of thesis Fig. 2.5. Depends on topology only. `bspline_leaves` = false makes every regular
/// node a terminal Bézier node instead (tests: with n = 4 the Fig. 2.5 rules are the B-spline's).
PlanTables build_plans(const PolygonTopology& topology, int max_depth, bool bspline_leaves = true);

}  // namespace gps
