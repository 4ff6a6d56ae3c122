#pragma once
// The CPU reference subdivision as triangles for drawing (`gpsurf render --reference N`).
#include "core/covariance_mesh.h"
#include "core/triangle_mesh.h"

namespace gps {

/// N levels of Catmull-Clark GPS subdivision with limit projection, faces fanned into triangles,
/// normals averaged from the faces around each vertex (area weighted).
TriangleMesh reference_triangles(const CovarianceMesh& mesh, int levels);

}  // namespace gps
