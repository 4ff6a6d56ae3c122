#pragma once
// Spinning a profile around an axis, as Blender's Spin does for edges: the profile is copied, rotated
// step by step, and consecutive copies are joined by quads (a lathe).
#include <vector>

#include "core/modelling/mesh_arrays.h"

namespace gps {

/// Spins the profile `vertices` (a chain in order, consecutive vertices joined; a loop when the last
/// is the first again) by `degrees` (right-handed about `axis`, 0 < |degrees| ≤ 360) around the line
/// through `center` along `axis`, in `steps` equal steps (at least 1; 3 for a full turn). Each step
/// appends a copy of the profile rotated exactly (μ′ = R(μ − c) + c, Σ′ = RΣRᵀ) and joins it to the
/// one before by a quad per profile edge; a full turn joins its last step to the profile itself (no
/// seam of duplicates). A vertex on the axis (within 1e-9 of the mesh's bounding-box diagonal) is not
/// copied: its quads become triangles, and an edge along the axis makes none. The quads run against a
/// profile edge's face where it has one (mesh-boundary edges: the band continues the surface), else
/// they face away from the axis (outward for a closed surface of revolution). Creases on profile
/// edges and corners go to their copies. Refuses a profile of fewer than 2 vertices, one that repeats
/// a vertex or runs along an edge with faces on both sides, boundary edges of opposite directions, a
/// full turn from an edge of the mesh (three faces would meet there), an axis that is zero and
/// numbers outside those ranges. Selection: the profile where the spin ends.
Modelled spin(const CovarianceMesh& mesh, const std::vector<int>& vertices, const Vec3& axis, const Vec3& center,
              double degrees, int steps);

}  // namespace gps
