#pragma once
// What of the corner pass's output (render/pipeline/corner_limit_pass.h) a change of topology leaves
// as it was. A patch whose plan the replanner kept (SurfaceReplanner::kept_patches) evaluates the same
// corners and midpoints again where it reads the same point values and its corner owners and edge
// neighbours are the same patches as before: what a slot evaluates is decided by those records and by
// patch order, which increasing kept runs preserve.
#include <functional>
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "core/plans/kept_patch_records.h"
#include "core/plans/patch_plans.h"
#include "core/plans/stencil_table.h"
#include "core/plans/surface_replanner.h"

namespace gps {

/// The patches of `after` (sorted), the plans of `mesh`, whose corner-pass output must be evaluated
/// again: those of patches_not_kept_alike (core/plans/kept_patch_records.h) for the change's kept runs
/// and relinked patches, and the kept ones that read a vertex whose Gaussian changed (`changed`, as
/// changed_gaussians gives it for the vertices' `origin`, as SurfaceRenderer::set_mesh takes it) or a
/// stencil row that reads one (`dependents`: of after's stencils, asked for only where a vertex that
/// was there before changed). A new vertex no kept plan reads. A plan reads only its face's piece (the
/// faces sharing a vertex with it; core/plans/surface_replanner.h, faces_reading): only the patches of
/// the faces whose pieces hold a changed vertex are looked at, unless most vertices changed. `first`: the
/// first patch of each face of `mesh` in `after` (first_patches, core/plans/patch_faces.h).
std::vector<int> stale_corner_patches(const SurfaceTables& before, const SurfaceTables& after,
                                      const CovarianceMesh& mesh, const std::vector<int>& first,
                                      const std::function<const StencilDependents&()>& dependents,
                                      const std::vector<int>& changed, const PlanChange& change,
                                      const std::vector<int>& origin);

/// Whether `after`, the tables after a change from `before` whose plans kept `kept` and whose
/// vertices came from `origin` (as set_mesh takes it), are `before` itself: every patch kept where
/// it was and every vertex where it was (the replanner then keeps every range as it was, bit for bit).
bool same_plans(const SurfaceTables& before, const SurfaceTables& after, const std::vector<KeptPatches>& kept,
                const std::vector<int>& origin);

}  // namespace gps
