#pragma once
// Framing by projected bounds: the camera placed so that the projections of a set of points (a mesh's
// silhouette) fill an image, or a part of it, rather than a sphere around their bounding box.
#include <glm/glm.hpp>
#include <vector>

#include "view/camera.h"

namespace gps {

/// A rectangle in normalised device coordinates (x right, y up); [-1, 1]² is the whole image.
struct NdcRect {
  glm::dvec2 lo{-1.0}, hi{1.0};
};

/// The rectangle of window pixels [pixel_min, pixel_max] (y down) of a window of size `window`.
NdcRect ndc_of_pixels(glm::vec2 window, glm::vec2 pixel_min, glm::vec2 pixel_max);

/// `camera` moved along and across its view direction (its angles, up axis, field of view and
/// projection kept) so that the projections of `points` fill `region` of an image of width / height
/// `aspect`, less `margin` (a fraction of the region's half-extent) at each side: the points touch
/// both sides of the region along one axis and are centred along the other, unless that would bring
/// the eye nearer the nearest point than a tenth of the points' extent (a needle seen end on): then the
/// eye stays that far and the points are centred along both. The target lies at the
/// depth of the points' bounding-box centre. `camera` unchanged for no points; points that all
/// coincide keep its distance.
Camera frame_silhouette(const Camera& camera, const std::vector<glm::dvec3>& points, double aspect,
                        const NdcRect& region = {}, double margin = 0.05);

/// The projected bounds of `points` seen by `camera` in an image of width / height `aspect`, in
/// normalised device coordinates (for checks of frame_silhouette()).
NdcRect projected_bounds(const Camera& camera, const std::vector<glm::dvec3>& points, double aspect);

}  // namespace gps
