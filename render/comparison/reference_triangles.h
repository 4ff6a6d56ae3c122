#pragma once
// The CPU reference subdivision as triangles for drawing (`gpsurf render --reference N`, the
// comparison images).
#include "core/mesh/covariance_mesh.h"
#include "core/plans/planned_surface.h"
#include "core/evaluation/triangle_mesh.h"
#include "render/gl/draw_options.h"
#include "view/camera.h"

namespace gps {

class SurfaceRenderer;

/// N levels of GPS subdivision with limit projection under the scheme `options` give for the mesh
/// (as the patches drawn with them), quads split along the diagonal the tessellator takes at the
/// same place, other faces fanned into triangles. Normals are the exact limit normals
/// (core/reference/limit_tangents.h), or where a vertex has none (a boundary vertex whose ring has no two
/// separated subdominant eigenvalues), averaged from the faces around it (area weighted). The
/// positions are about the mesh's evaluation origin (core/mesh/covariance_mesh.h).
PlacedTriangles reference_triangles(const CovarianceMesh& mesh, int levels, const PlanOptions& options = {});

/// The same reference vertices (Catmull-Clark, N levels) in the patches' own triangles at
/// tessellation level 2^N (render/comparison/patch_triangles.h): each vertex of the GPU's tessellation is a
/// vertex of the reference, found by its patch parameters on the 2^-N grid. Drawn against the
/// patches, the difference images then show the two surfaces' values alone, not also the rounding
/// of two different triangulations, which the amplified normal images would show. `mesh` is the
/// renderer's mesh, drawn at options `o` with o.level = 2^N; throws where a vertex is off the grid.
PlacedTriangles reference_in_patch_triangles(SurfaceRenderer& renderer, const CovarianceMesh& mesh,
                                             const Camera& camera, const DrawOptions& o, int width, int height,
                                             int levels);

}  // namespace gps
