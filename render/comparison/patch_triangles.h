#pragma once
// The GPU's own tessellation, its vertices given values on the CPU: what `render --exact` and
// `render --reference` (Catmull-Clark) draw, so that two images of one surface differ in its values alone.
#include <functional>

#include "core/mesh/linalg.h"
#include "core/evaluation/triangle_mesh.h"
#include "render/gl/draw_options.h"
#include "view/camera.h"

namespace gps {

class SurfaceRenderer;

/// A point of the surface at patch parameters: its position and unit normal (zero: none there).
struct SurfaceValues {
  Vec3 position, normal;
};
using SurfaceAt = std::function<SurfaceValues(int patch, double u, double v)>;

/// The triangles the renderer's patches tessellate into for `o` in a width × height view (captured
/// by transform feedback), with the corners in the order the GPU drew them, each vertex at the
/// values `surface_at` gives at its patch parameters: once per point, at the canonical patch of a
/// point on a patch edge (shaders/canonical_edge.glsl), at its own patch's on an infinitely sharp
/// crease, where each side has its own normal (TessellatedVertex::on_crease). Drawn as static
/// triangles they rasterise as the patches do, triangle for triangle and corner for corner: the
/// images differ where the values do. A vertex `surface_at` gives no normal takes the
/// area-weighted normal of its triangles.
TriangleMesh patch_triangles(SurfaceRenderer& renderer, const Camera& camera, const DrawOptions& o, int width,
                             int height, const SurfaceAt& surface_at);

}  // namespace gps
