#pragma once
// The size of a uniform tessellation, known from the patches and the level before any evaluation.
#include "core/plans/patch_plans.h"
#include "core/support/memory_budget.h"

namespace gps {

/// The vertices and triangles tessellate() makes from `plans` at `level`: (L+1)² grid points and
/// 2L² triangles per quad patch (L halved on a split face's half-size patches; at an odd level, the
/// fans beside them), (L+1)(L+2)/2 points and L² triangles per triangle patch. Points on shared patch
/// edges are counted in each patch and fans at their most: upper bounds. The memory is what it holds
/// at its peak for them (its arrays' growth and the maps of shared samples included).
OutputSize tessellation_size(const PatchPlans& plans, int level);

}  // namespace gps
