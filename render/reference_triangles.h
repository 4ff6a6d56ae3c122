#pragma once
// The CPU reference subdivision as triangles for drawing (`gpsurf render --reference N`).
#include <functional>
#include <vector>

#include "core/covariance_mesh.h"
#include "core/patch_layout.h"
#include "core/planned_surface.h"
#include "core/triangle_mesh.h"

namespace gps {

struct TessellatedVertex;  // render/patch_draw.h

/// Which diagonal splits a quad of the reference, given its four corners' patch parameters: 0 from
/// corner 0 to corner 2, 1 from corner 1 to corner 3.
using QuadSplit = std::function<int(const PatchParam* corners)>;

/// N levels of GPS subdivision with limit projection under the scheme `options` give for the mesh
/// (as the patches drawn with them), quads split along the diagonal the tessellator takes at the
/// same place (`split`; none: the rule of Mesa's tessellator), other faces fanned into triangles.
/// Normals are the exact limit normals (core/limit_tangents.h), or where a vertex has none (a
/// boundary vertex whose ring has no two separated subdominant eigenvalues), averaged from the
/// faces around it (area weighted).
TriangleMesh reference_triangles(const CovarianceMesh& mesh, int levels, const PlanOptions& options = {}, const QuadSplit& split = {});

/// The diagonals in the triangles a GPU's tessellator made (SurfaceRenderer::capture_vertices at
/// the uniform level 2^N): tessellators differ (NVIDIA's are not Mesa's), and interpolating across
/// the other diagonal moved the reference's normals by up to 5e-4 in the ×5000 comparison images.
QuadSplit tessellator_split(const std::vector<TessellatedVertex>& triangles);

}  // namespace gps
