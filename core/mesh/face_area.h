#pragma once
// Whether a polygon has a surface at a length tolerance, as the repair drops faces without one
// (core/io/mesh_repair.h) and the modelling operations refuse to make them.
#include <algorithm>
#include <span>

#include <Eigen/Geometry>

#include "core/mesh/linalg.h"

namespace gps {

/// Whether the polygon of `corners`, whose positions `position(corner)` gives, is thinner than
/// `tolerance`: its corners lie within it of the line through its longest edge (in a line, or
/// together), or its area is no more than half the tolerance times that edge (a triangle's height
/// below the tolerance; a polygon folded onto itself). Measured from its first corner, so that it
/// does not change where the mesh lies.
template <class Position>
bool without_area(std::span<const int> corners, const Position& position, double tolerance) {
  if (corners.empty()) return true;
  const Vec3 origin = position(corners[0]);
  Vec3 normal = Vec3::Zero();  // Newell's: twice the vector area
  Vec3 from = Vec3::Zero(), along = Vec3::Zero();
  double longest = 0;
  for (size_t k = 0; k < corners.size(); ++k) {
    const Vec3 p = position(corners[k]) - origin, q = position(corners[(k + 1) % corners.size()]) - origin;
    normal += p.cross(q);
    if (const double length = (q - p).norm(); length > longest) {
      longest = length;
      from = p;
      along = (q - p) / length;
    }
  }
  if (0.5 * normal.norm() <= 0.5 * tolerance * longest) return true;
  for (const int c : corners) {
    const Vec3 d = position(c) - origin - from;
    if ((d - d.dot(along) * along).norm() > tolerance) return false;
  }
  return true;
}

}  // namespace gps
