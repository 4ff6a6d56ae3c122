#pragma once
// The camera of a render (gpsurf render, Python's render): the angles asked for, framed so that the
// limit surface's silhouette fills the image (view/silhouette_framing.h).
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "render/gl/draw_options.h"
#include "view/camera.h"

namespace gps {

class SurfaceRenderer;

/// The limit surface's points that framing looks at, in the renderer's frame (frame()): the vertices
/// the tessellator makes for the renderer's mesh at a uniform level (coarser for more patches), or
/// past 16,384 patches the patch corners the compute passes evaluated; with the base mesh's means
/// where `o` draws its lines, and the corners of the boxes around the ellipsoids where it draws those.
std::vector<glm::dvec3> framing_points(SurfaceRenderer& renderer, const CovarianceMesh& mesh, const DrawOptions& o);

/// The camera a render asks for: `yaw_pitch_distance` {} for the default angles, {yaw, pitch} in
/// degrees, a third value replacing the framed distance; `up_axis` 0 x, 1 y, 2 z. The renderer holds
/// `mesh` (set_mesh); the silhouette of framing_points() fills the width × height image less a margin.
/// Framed in the renderer's frame and mapped to the world: invariant to the mesh's position and scale.
Camera render_camera(SurfaceRenderer& renderer, const CovarianceMesh& mesh,
                     const std::vector<float>& yaw_pitch_distance, int up_axis, const DrawOptions& o, int width,
                     int height);

}  // namespace gps
