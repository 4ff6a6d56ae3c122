// A scalar per control vertex carried to the limit surface: the same limit weights as the points.
#include <gtest/gtest.h>

#include "core/fitting/limit_fit.h"
#include "core/fitting/limit_scalars.h"
#include "core/fitting/surface_distance.h"
#include "core/support/error.h"
#include "core/modelling/samples.h"

namespace gps {
namespace {

TEST(LimitScalars, ACoordinateOfTheMeansIsTheLimitPointsCoordinateUnderEqualCovariances) {
  // Equal isotropic covariances make the limit the linear scheme's, linear in the means: a scalar
  // equal to a coordinate of the means is that coordinate of the limit surface.
  const CovarianceMesh mesh = with_isotropic_covariances(make_sample("icosphere", 80));
  const PlannedSurface surface(mesh, PlanOptions{});
  const std::vector<Vec3> points = limit_surface_triangles(mesh, 3).triangles.positions;
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double> scalars;
    for (size_t i = 0; i < mesh.n_vertices(); ++i) scalars.push_back(mesh.mean(i)[axis]);
    const std::vector<double> values = limit_scalars_at(surface, scalars, points);
    ASSERT_EQ(values.size(), points.size());
    for (size_t i = 0; i < points.size(); ++i) EXPECT_NEAR(values[i], points[i][axis], 1e-9) << "point " << i;
  }
}

TEST(LimitScalars, AConstantStaysConstantOnAnyGaussians) {
  const CovarianceMesh mesh = make_sample("pawn");
  const PlannedSurface surface(mesh, PlanOptions{});
  const std::vector<Vec3> points = limit_surface_triangles(mesh, 2).triangles.positions;
  for (const double value : limit_scalars_at(surface, std::vector<double>(mesh.n_vertices(), 2.5), points))
    EXPECT_NEAR(value, 2.5, 1e-12);
}

TEST(LimitScalars, RefusesScalarsThatAreNotOneFiniteNumberPerVertex) {
  const CovarianceMesh mesh = make_sample("cone");
  const PlannedSurface surface(mesh, PlanOptions{});
  const std::vector<Vec3> points{Vec3::Zero()};
  EXPECT_THROW(limit_scalars_at(surface, std::vector<double>(mesh.n_vertices() + 1, 0.0), points), Error);
  std::vector<double> scalars(mesh.n_vertices(), 0.0);
  scalars[1] = NAN;
  EXPECT_THROW(limit_scalars_at(surface, scalars, points), Error);
}

}  // namespace
}  // namespace gps
