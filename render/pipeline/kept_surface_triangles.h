#pragma once
// What of the surface cache's triangles (render/cache/surface_cache.h) a change of topology leaves as
// they were: a patch generates the same triangles under the same number where it keeps its number,
// its corner-pass output (render/pipeline/kept_corner_output.h) and the patches it evaluates boundary
// points from (its edge neighbours and corner owners, core/plans/patch_adjacency.h).
#include <vector>

#include "core/plans/patch_plans.h"
#include "core/plans/surface_replanner.h"

namespace gps {

/// The patches of `after` (sorted) whose triangles change: those not kept under their old number
/// (patches not kept, kept runs that moved), those of `stale_corners` (sorted: stale_corner_patches),
/// and those that evaluate a boundary point from one of these.
std::vector<int> patches_whose_triangles_change(const PatchPlans& after, const std::vector<KeptPatches>& kept,
                                                const std::vector<int>& stale_corners);

}  // namespace gps
