#pragma once
// The CPU reference subdivision as triangles for drawing (`gpsurf render --reference N`).
#include "core/covariance_mesh.h"
#include "core/planned_surface.h"
#include "core/triangle_mesh.h"

namespace gps {

/// N levels of GPS subdivision with limit projection under the scheme `options` give for the mesh
/// (as the patches drawn with them), quads split along the diagonal the tessellator takes at the
/// same place, other faces fanned into triangles. Normals are the exact limit normals
/// (core/limit_tangents.h), or where a vertex has none (a boundary vertex whose ring has no two
/// separated subdominant eigenvalues), averaged from the faces around it (area weighted).
TriangleMesh reference_triangles(const CovarianceMesh& mesh, int levels, const PlanOptions& options = {});

}  // namespace gps
