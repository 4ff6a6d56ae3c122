#pragma once
// A scalar per control vertex carried to the limit surface as a primvar: it subdivides linearly, with
// the same limit weights over the control vertices as the surface's 9D points (core/fitting/limit_weights.h).
#include <vector>

#include "core/mesh/linalg.h"
#include "core/plans/planned_surface.h"

namespace gps {

/// The limit value of `scalars` (one per control vertex of `surface`) at the limit point closest to
/// each of `points` (core/fitting/closest_points.h, tessellated at `level`). Throws gps::Error where
/// the scalars are not one finite number per control vertex.
std::vector<double> limit_scalars_at(const PlannedSurface& surface, const std::vector<double>& scalars,
                                     const std::vector<Vec3>& points, int level = 6);

}  // namespace gps
