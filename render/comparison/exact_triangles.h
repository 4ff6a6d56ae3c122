#pragma once
// The GPU's own tessellation with the CPU's exact values (`gpsurf render --exact`).
#include "core/mesh/covariance_mesh.h"
#include "core/evaluation/triangle_mesh.h"
#include "render/gl/draw_options.h"
#include "view/camera.h"

namespace gps {

class SurfaceRenderer;

/// The triangles the renderer's patches tessellate into for `o` in a width × height view (captured
/// by transform feedback), each vertex at its patch parameters evaluated by the CPU evaluator in
/// double (core/evaluation/patch_eval.h; equal to subdivision with limit projection at every parameter). Drawn
/// as static triangles, they rasterise as the patches do, so that the difference of their AOVs is
/// the GPU's float error alone, at any level and under either scheme. (No reference level has the
/// vertices of GL's triangle tessellation: its inner rings lie off the dyadic grid.) `mesh` is the
/// renderer's mesh; the positions are about its evaluation origin (core/mesh/covariance_mesh.h).
PlacedTriangles exact_triangles(SurfaceRenderer& renderer, const CovarianceMesh& mesh, const Camera& camera,
                                const DrawOptions& o, int width, int height);

}  // namespace gps
