#pragma once
// Uniform tessellation of every patch into a watertight triangle mesh (the CPU twin of the GPU's
// uniform tessellation levels).
#include "core/plans/patch_plans.h"
#include "core/evaluation/triangle_mesh.h"
#include "core/support/progress.h"

namespace gps {

/// Every patch at level L (1..64): an (L+1)² grid of limit points, two triangles per cell; a split
/// face's half-size patches an (L/2+1)² grid when L is even (L segments along every mesh edge).
/// Samples on a patch corner or a shared patch edge are evaluated once and shared, so the mesh is
/// watertight. Throws gps::Error if a sample leaves the cone of positive definite matrices.
/// `progress` hears the share of the patches done about a hundred times (Cancelled when it says stop).
TriangleMesh tessellate(const PatchPlans& plans, const std::vector<Dual>& points, int level,
                        const ProgressReport& progress = {});

}  // namespace gps
