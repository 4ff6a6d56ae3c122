#include "render/overlays/distance_ramp.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace gps {

namespace {

struct Stop {
  float t;
  glm::vec3 colour;
};

// Through cyan rather than straight from blue to yellow, whose midpoint is the surface's own grey.
constexpr std::array<Stop, 5> kStops = {{{0.0f, {0.16f, 0.38f, 1.0f}},
                                         {0.3f, {0.05f, 0.78f, 0.88f}},
                                         {0.55f, {1.0f, 0.87f, 0.12f}},
                                         {0.78f, {1.0f, 0.5f, 0.08f}},
                                         {1.0f, {0.9f, 0.08f, 0.08f}}}};

}  // namespace

glm::vec3 ramp_colour(float t) {
  t = std::isnan(t) ? 0.0f : std::clamp(t, 0.0f, 1.0f);
  for (size_t i = 1; i < kStops.size(); ++i)
    if (t <= kStops[i].t) {
      const Stop &a = kStops[i - 1], &b = kStops[i];
      return glm::mix(a.colour, b.colour, (t - a.t) / (b.t - a.t));
    }
  return kStops.back().colour;
}

float ramp_position(double distance, double max_distance) {
  if (std::isnan(distance) || !(max_distance > 0.0) || !std::isfinite(max_distance)) return 0.0f;
  return float(std::clamp(distance / max_distance, 0.0, 1.0));
}

}  // namespace gps
