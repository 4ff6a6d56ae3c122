#pragma once
// Welding positions: which points of a mesh are one, bit-equal (−0 as 0) or within a distance of one
// another, in time linear in the points however they crowd.
#include <vector>

#include "core/mesh/linalg.h"

namespace gps {

/// Per position: the lowest index of its cluster, the positions joined where they are equal or, with
/// `tolerance` > 0, within that distance of one another (transitively: single linkage).
std::vector<int> weld_roots(const std::vector<Vec3>& positions, double tolerance);

}  // namespace gps
