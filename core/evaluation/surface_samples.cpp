#include "core/evaluation/surface_samples.h"

namespace gps {

TriangleMesh tessellate(const PlannedSurface& surface, int level, const ProgressReport& progress) {
  TriangleMesh out = tessellate(surface.tables().plans, surface.points(), level, progress);
  if (!surface.origin().isZero())
    for (Vec3& p : out.positions) p += surface.origin();
  return out;
}

std::optional<PatchSample> evaluate_patch(const PlannedSurface& surface, int patch, double u, double v) {
  std::optional<PatchSample> s = evaluate_patch(surface.tables().plans, surface.points(), patch, u, v);
  if (s) s->position += surface.origin();
  return s;
}

}  // namespace gps
