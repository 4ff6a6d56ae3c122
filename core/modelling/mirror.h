#pragma once
// Mirroring a mesh, as Blender's Mirror (modifier, applied) does: the mesh and its mirror image about
// an axis-aligned plane, joined along the plane into one part when they meet there.
#include "core/modelling/mesh_arrays.h"

namespace gps {

/// Appends the mirror image of the whole mesh about the plane through `center` perpendicular to axis
/// `axis` (0 x, 1 y, 2 z): every vertex copied with μ′ = M(μ − c) + c and Σ′ = MΣMᵀ (M flips the
/// axis), every face copied with its corners reversed (keeping the first) so that the copy stays
/// outward; creases and corners are copied too. With `merge`, a vertex on the plane (within 1e-5 of
/// the mesh's bounding-box diagonal) is not copied: it serves both halves, its Gaussian the 9D average
/// of itself and its image (symmetric about the plane, so that the surface is). The seam must then be
/// manifold: refuses an edge on the plane with faces on both sides, a face on the plane, and a vertex
/// on the plane beside no boundary edge along it (the halves would meet at a point). Selection: the
/// copies. The vertices and faces keep their indices (0 … n−1) and the copies follow in vertex order,
/// so that an edit of the mesh can be shown on the result by index (mirror_images, update_mirrored).
Modelled mirror(const CovarianceMesh& mesh, int axis, const Vec3& center, bool merge);

/// How near the plane a vertex lies that mirror() merges: 1e-5 of the mesh's bounding-box diagonal.
double mirror_merge_distance(const CovarianceMesh& mesh);

/// The index each vertex's image has in mirror()'s result: the vertex itself where it is merged on
/// the plane, else n + its rank among the vertices not merged.
std::vector<int> mirror_images(const CovarianceMesh& mesh, int axis, const Vec3& center, bool merge);

/// Sets in `mirrored` (mirror()'s result for a mesh of `mesh`'s faces, whose images were `images`)
/// the Gaussians mirror() would give `vertices` of `mesh` and their images: the mesh's edit shown on
/// both sides at the cost of the vertices changed. Returns the vertices of `mirrored` set, ascending.
/// Throws gps::Error where a merged vertex's symmetric covariance is not positive definite.
std::vector<int> update_mirrored(const CovarianceMesh& mesh, const std::vector<int>& vertices, int axis,
                                 const Vec3& center, const std::vector<int>& images, CovarianceMesh& mirrored);

}  // namespace gps
