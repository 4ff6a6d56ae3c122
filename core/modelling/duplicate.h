#pragma once
// Duplicating faces, as Blender's Duplicate does: a copy of the faces and their vertices as a new
// part, moved by an offset.
#include <vector>

#include "core/modelling/mesh_arrays.h"

namespace gps {

/// Appends a copy of the faces (checked; none is refused) moved by `offset`: each vertex of them is
/// copied with its mean moved and its covariance kept (a translation carries a Gaussian exactly), one
/// copy for each fan of the faces around it (as extrude's sectors, core/modelling/extrude.h), so that
/// faces meeting only at a vertex give a manifold copy. The copies' faces keep the originals' corner
/// order, creases and corners. The input's vertices and faces keep their indices. Selection: the
/// copied vertices.
Modelled duplicate_faces(const CovarianceMesh& mesh, const std::vector<int>& faces, const Vec3& offset);

}  // namespace gps
