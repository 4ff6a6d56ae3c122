// Closest points on a limit surface (core/fitting/closest_points.h), the fit's correspondences: points
// on a creased box's limit surface are found on it, also beyond the corners where the parameters of
// a patch stretch, and between a patch border's chords and the border itself.
#include "core/fitting/closest_points.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/fitting/mesh_simplification.h"
#include "core/mesh/crease_by_angle.h"
#include "core/mesh/inference.h"
#include "core/modelling/samples.h"
#include "core/plans/planned_surface.h"

namespace gps {
namespace {

TEST(ClosestLimitPoints, PointsOnACreasedBoxAreFoundOnIt) {
  // A sphere's triangles pushed out onto the box [−1, 1]³, creased along its edges and simplified: a
  // box of sixty vertices, extraordinary ones on its faces, whose limit surface is the box itself.
  CovarianceMesh dense = make_sample("sphere", 6000);
  std::vector<Vec3> means = dense.means();
  for (size_t v = 0; v < means.size(); ++v) dense.set_mean(v, means[v] / means[v].cwiseAbs().maxCoeff());
  crease_by_angle(dense, 30);
  infer_covariances(dense);
  SimplifyOptions options;
  options.target_vertices = 60;
  const CovarianceMesh box = simplify_mesh(dense, options).mesh;
  const PlannedSurface surface(box, PlanOptions{});
  std::vector<Vec3> targets = dense.means();
  for (Vec3& p : targets) p -= surface.origin();
  const std::vector<SurfacePoint> found = closest_limit_points(surface.tables().plans, surface.points(), targets, 6);
  double worst = 0;
  for (const SurfacePoint& s : found) worst = std::max(worst, s.distance);
  EXPECT_LT(worst, 1e-12);
}

}  // namespace
}  // namespace gps
