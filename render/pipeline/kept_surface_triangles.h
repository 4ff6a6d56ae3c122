#pragma once
// What of the surface cache's triangles (render/cache/surface_cache.h) a change of topology leaves as
// they were: a patch kept by the change (render/pipeline/kept_corner_output.h) generates the same
// triangles, under its new number, where its corner-pass output is kept and so are the patches it
// evaluates boundary points from (its edge neighbours and corner owners, core/plans/patch_adjacency.h).
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "core/plans/patch_plans.h"
#include "core/plans/surface_replanner.h"

namespace gps {

struct KeptTriangles {
  std::vector<int> new_number;  // per patch before the change: its number after it, −1 where not kept
  std::vector<char> changed;    // per patch after it: whether its triangles change
};

/// For a change from tables of `n_before` patches to `after`, the plans of `mesh` (`kept`: its runs,
/// which must fit, kept_runs_fit), with the patches whose corner-pass output is evaluated again
/// `stale_corners` (stale_corner_patches): the patches whose triangles change are those not kept,
/// those of `stale_corners`, and those that evaluate a boundary point from one of these, which lie on
/// the faces around theirs (only those are looked at, unless many changed). `first`: the first patch of
/// each face of `mesh` in `after` (first_patches, core/plans/patch_faces.h).
KeptTriangles kept_triangles(const CovarianceMesh& mesh, const PatchPlans& after, const std::vector<int>& first,
                             int n_before, const std::vector<KeptPatches>& kept, const std::vector<int>& stale_corners);

}  // namespace gps
