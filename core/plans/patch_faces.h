#pragma once
// Which base face each patch of a planned surface lies on, and back: the patches of some faces
// (patch numbering: core/plans/patch_layout.h for Catmull-Clark, one patch per triangle for Loop).
#include <vector>

#include "core/mesh/mesh_connectivity.h"
#include "core/plans/patch_plans.h"

namespace gps {

/// The first patch of each face of `topology` in `plans`, planned for a mesh of these faces, and the
/// patch count at the end. Throws gps::Error where the plans' patches do not follow the mesh's faces.
std::vector<int> first_patches(const PolygonTopology& topology, const PatchPlans& plans);

/// The base face of each patch of `plans`, planned for a mesh of these faces. Throws gps::Error where the plans'
/// patches do not follow the mesh's faces (plans of another mesh).
std::vector<int> patch_faces(const PolygonTopology& topology, const PatchPlans& plans);

/// The patches of `plans` that lie on `faces` (any order, repeats allowed), ascending. Throws
/// gps::Error as patch_faces() does, or naming a face the mesh does not have.
std::vector<int> patches_of_faces(const PolygonTopology& topology, const PatchPlans& plans,
                                  const std::vector<int>& faces);
/// The same from the faces' first patches (first_patches), as a caller that keeps them has them.
std::vector<int> patches_of_faces(const std::vector<int>& first, const std::vector<int>& faces);

}  // namespace gps
