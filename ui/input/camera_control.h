#pragma once
// Mouse-driven camera moves of the editor: orbit, pan, zoom to the cursor, frame all or a selection.
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh/covariance_mesh.h"
#include "view/camera.h"

namespace gps {

/// Turns the camera around its target: `delta` window pixels of mouse motion, 0.4° per pixel;
/// pitch stays inside ±89°.
void orbit(Camera& camera, glm::vec2 delta);

/// Slides the camera in its view plane so that the point at the target's depth under the cursor
/// follows the mouse (`delta` window pixels, `height` the window height).
void pan(Camera& camera, glm::vec2 delta, int height);

/// Zooms by 0.85^steps toward `anchor` (the surface point under the cursor; else the point at the
/// target's depth): a homothety of the camera about the anchor, which stays under the cursor.
void zoom_to_cursor(Camera& camera, float steps, int width, int height, glm::vec2 cursor,
                    std::optional<glm::dvec3> anchor);

/// The camera at the same angles framing the given points (all of them in view); `camera` unchanged
/// when there are none. Points closer than `min_radius` to their centre are framed at that radius.
Camera frame_points(const Camera& camera, const CovarianceMesh& mesh, const std::vector<int>& vertices,
                    double min_radius);

/// The camera at the same angles and projection whose view of the points (their projected bounds,
/// view/silhouette_framing.h) fills the window-pixel rectangle [region_min, region_max] of a window of
/// size `window` (the part the panels leave free), less a margin: the editor's first view and Home.
/// Points closer than `min_radius` to their centre are framed at that radius.
Camera frame_points_in_region(const Camera& camera, const CovarianceMesh& mesh, const std::vector<int>& vertices,
                              double min_radius, glm::vec2 window, glm::vec2 region_min, glm::vec2 region_max);

}  // namespace gps
