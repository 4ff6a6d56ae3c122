#include "core/fitting/limit_scalars.h"

#include <cmath>
#include <string>

#include "core/fitting/closest_points.h"
#include "core/fitting/limit_weights.h"
#include "core/support/error.h"

namespace gps {

std::vector<double> limit_scalars_at(const PlannedSurface& surface, const std::vector<double>& scalars,
                                     const std::vector<Vec3>& points, int level) {
  const size_t vertices = size_t(surface.tables().stencils.n_base);
  if (scalars.size() != vertices)
    throw Error("expected one scalar per control vertex (" + std::to_string(vertices) + "), got " +
                std::to_string(scalars.size()));
  for (size_t i = 0; i < scalars.size(); ++i)
    if (!std::isfinite(scalars[i])) throw Error("the scalar of vertex " + std::to_string(i) + " is not finite");
  if (points.empty()) return {};
  const SurfaceTables& tables = surface.tables();
  // The plans' points are about the surface's origin: so are the points looked up on it.
  std::vector<Vec3> about_origin(points);
  for (Vec3& p : about_origin) p -= surface.origin();
  const std::vector<SurfacePoint> closest = closest_limit_points(tables.plans, surface.points(), about_origin, level);
  std::vector<double> out(points.size());
#pragma omp parallel for schedule(static)
  for (ptrdiff_t i = 0; i < ptrdiff_t(points.size()); ++i) {
    const SurfacePoint& at = closest[size_t(i)];
    const LimitWeights w = limit_weights(tables.plans, tables.stencils, at.patch, at.u, at.v);
    double value = 0;
    for (size_t k = 0; k < w.size(); ++k) value += w.value[k] * scalars[size_t(w.vertex[k])];
    out[size_t(i)] = value;
  }
  return out;
}

}  // namespace gps
