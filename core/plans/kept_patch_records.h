#pragma once
// Which patches a replanner kept (core/plans/surface_replanner.h) still have the adjacency records
// they had (core/plans/patch_adjacency.h): the same corner owners and edge neighbours, renumbered.
// What the corner pass and the surface cache keep of a kept patch rests on it.
#include <vector>

#include "core/plans/patch_plans.h"
#include "core/plans/surface_replanner.h"

namespace gps {

/// Whether `kept` maps patches of tables of `n_before` patches onto tables of `n_after`: every run
/// inside both, the runs increasing in both numberings.
bool kept_runs_fit(const std::vector<KeptPatches>& kept, int n_before, int n_after);

/// Per patch of `after`: true for a patch not kept, or a kept one whose owner or neighbour records
/// name other patches (or say otherwise) than before. `kept` must fit (kept_runs_fit). `relinked`:
/// the kept patches whose records may differ (PlanChange::relinked), the only ones compared; null:
/// every kept patch is.
std::vector<char> patches_not_kept_alike(const PatchPlans& before, const PatchPlans& after,
                                         const std::vector<KeptPatches>& kept,
                                         const std::vector<int>* relinked = nullptr);

}  // namespace gps
