#pragma once
// Placing a coarse mesh's vertices for its limit surface: a subdivision surface lies inside its
// control mesh where it curves, so a simplified scan's limit surface looks shrunk. Moving each mean
// out by how far its vertex's limit position falls short of it puts the limit surface back near the
// positions the simplification kept, which lie on the input.
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "core/plans/planned_surface.h"

namespace gps {

struct LimitPlacement {
  CovarianceMesh mesh;
  /// The rms distance between the vertices' limit positions and their positions in the mesh given,
  /// over its bounding-box diagonal, before and after the placement.
  double gap_before = 0, gap_after = 0;
};

/// The mesh with its means moved for its limit surface, covariances and sharpness unchanged: `steps`
/// times μ ← μ + (p − L(μ)), p the positions in `mesh` and L each vertex's exact limit position (the
/// reference's limit projection, core/reference/reference_subdivision.h, under the scheme `options`
/// pick). For fixed covariances L is linear in the means, L(μ) = K⁻¹ Σₖ wₖ Σₖ⁻¹ μₖ, a low-pass filter
/// whose gain is near 1 on the smooth shape and falls toward the mesh's finest scale. One step
/// undoes the shrinkage of the smooth shape to first order (gain 2λ − λ² for a gain λ); many steps
/// converge to L(μ) = p, interpolation, which amplifies the finest scale up to 1/λ and makes
/// ripples between the vertices. Throws gps::Error as the reference does for a mesh it cannot
/// subdivide, or where a moved mean is out of range.
LimitPlacement place_for_limit(const CovarianceMesh& mesh, const PlanOptions& options, int steps = 1);

}  // namespace gps
