#pragma once
// The colour ramp of the target-point overlay: a point's distance from the surface, from 0 (on it) to
// the ramp's maximum and beyond, as blue → cyan → yellow → orange → red. No GL: the overlay's ramp
// texture and the editor's legend are both made from it.
#include <glm/glm.hpp>

namespace gps {

/// The ramp at t, clamped to [0, 1]: blue at 0, yellow at about the middle, red at 1.
glm::vec3 ramp_colour(float t);

/// Where `distance` lies on a ramp that ends at `max_distance`: distance / max_distance clamped to
/// [0, 1]; 0 for a distance that is not a number or a maximum that is not positive and finite.
float ramp_position(double distance, double max_distance);

/// The colour of `distance` on a ramp that ends at `max_distance`.
inline glm::vec3 distance_colour(double distance, double max_distance) {
  return ramp_colour(ramp_position(distance, max_distance));
}

}  // namespace gps
