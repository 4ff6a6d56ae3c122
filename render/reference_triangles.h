#pragma once
// The CPU reference subdivision as triangles for drawing (`gpsurf render --reference N`).
#include "core/covariance_mesh.h"
#include "core/planned_surface.h"
#include "core/triangle_mesh.h"

namespace gps {

/// N levels of GPS subdivision with limit projection under the scheme `options` give for the mesh
/// (as the patches drawn with them), faces fanned into triangles, normals averaged from the faces
/// around each vertex (area weighted).
TriangleMesh reference_triangles(const CovarianceMesh& mesh, int levels, const PlanOptions& options = {});

}  // namespace gps
