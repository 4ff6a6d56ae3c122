#pragma once
// Whether a polygon has a surface at a length tolerance, as the repair drops faces without one
// (core/io/mesh_repair.h) and the modelling operations refuse to make them.
#include <algorithm>
#include <span>

#include <Eigen/Geometry>

#include "core/mesh/linalg.h"

namespace gps {

/// Whether the polygon of `corners`, whose positions `position(corner)` gives, has no more area than
/// `tolerance` times its longest edge (its height below the tolerance: corners in a line, or together).
template <class Position>
bool without_area(std::span<const int> corners, const Position& position, double tolerance) {
  Vec3 normal = Vec3::Zero();  // Newell's: twice the vector area
  double longest = 0;
  for (size_t k = 0; k < corners.size(); ++k) {
    const Vec3 &p = position(corners[k]), &q = position(corners[(k + 1) % corners.size()]);
    normal += p.cross(q);
    longest = std::max(longest, (q - p).norm());
  }
  return 0.5 * normal.norm() <= tolerance * longest;
}

}  // namespace gps
