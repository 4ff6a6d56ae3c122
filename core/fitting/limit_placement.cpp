#include "core/fitting/limit_placement.h"

#include <cmath>

#include "core/reference/reference_subdivision.h"

namespace gps {
namespace {

// Per vertex, its position in `wanted` less its exact limit position in `mesh`.
std::vector<Vec3> limit_shortfalls(const CovarianceMesh& mesh, const std::vector<Vec3>& wanted,
                                   const SubdivisionOptions& limit) {
  const CovarianceMesh limits = subdivide(mesh, limit).mesh;
  std::vector<Vec3> shortfalls(wanted.size());
  for (size_t v = 0; v < wanted.size(); ++v) shortfalls[v] = wanted[v] - limits.mean(v);
  return shortfalls;
}

double rms(const std::vector<Vec3>& offsets) {
  double sum = 0;
  for (const Vec3& d : offsets) sum += d.squaredNorm();
  return offsets.empty() ? 0.0 : std::sqrt(sum / double(offsets.size()));
}

}  // namespace

LimitPlacement place_for_limit(const CovarianceMesh& mesh, const PlanOptions& options, int steps) {
  SubdivisionOptions limit;
  limit.scheme = scheme_for(mesh.topology(), options);
  limit.levels = 0;
  limit.limit = true;
  limit.loop_beta = options.loop_beta;
  const double diagonal = bounding_box_diagonal(mesh);
  const double scale = diagonal > 0 ? diagonal : 1.0;
  LimitPlacement placed{mesh, 0, 0};
  std::vector<Vec3> shortfalls = limit_shortfalls(mesh, mesh.means(), limit);
  placed.gap_before = rms(shortfalls) / scale;
  for (int step = 0; step < steps; ++step) {
    for (size_t v = 0; v < shortfalls.size(); ++v) placed.mesh.set_mean(v, placed.mesh.mean(v) + shortfalls[v]);
    validate_gaussians(placed.mesh, "the mesh placed for its limit surface");
    shortfalls = limit_shortfalls(placed.mesh, mesh.means(), limit);
  }
  placed.gap_after = rms(shortfalls) / scale;
  return placed;
}

}  // namespace gps
