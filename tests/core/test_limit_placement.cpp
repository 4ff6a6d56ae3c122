// Placing a coarse mesh's vertices for its limit surface: a flat grid is left where it is, equal
// covariances take one step of the linear scheme's limit, and a simplified sphere's limit surface
// comes back to the sphere without ripples.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/fitting/limit_placement.h"
#include "core/fitting/mesh_simplification.h"
#include "core/fitting/surface_distance.h"
#include "core/modelling/samples.h"
#include "core/reference/reference_subdivision.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

CovarianceMesh with_covariance(CovarianceMesh mesh, const Mat3& covariance) {
  for (size_t v = 0; v < mesh.n_vertices(); ++v) mesh.set_covariance(v, covariance);
  return mesh;
}

double max_offset(const CovarianceMesh& a, const CovarianceMesh& b) {
  double offset = 0;
  for (size_t v = 0; v < a.n_vertices(); ++v) offset = std::max(offset, (a.mean(v) - b.mean(v)).norm());
  return offset;
}

TEST(LimitPlacement, AFlatRegularGridStaysWhereItIs) {
  // Its limit positions are its positions (interior, straight boundary and corners alike).
  const CovarianceMesh grid = test::grid_mesh(6, 6, 0.3, true);
  const LimitPlacement placed = place_for_limit(grid, PlanOptions{});
  EXPECT_LT(placed.gap_before, 1e-15);
  EXPECT_LT(max_offset(placed.mesh, grid), 1e-14);
}

TEST(LimitPlacement, EqualCovariancesTakeOneStepOfTheLinearScheme) {
  // With every covariance the same, the GPS limit is the linear scheme's limit of the means, S p
  // (subdivide_points, which never maps to 9D): one step gives p + (p − S p). Loop on triangles,
  // Catmull-Clark on quads, and Catmull-Clark with creases and a corner.
  CovarianceMesh creased = make_sample("cube");
  creased.sharpness.set_crease(creased.face(0)[0], creased.face(0)[1], 2.0);
  creased.sharpness.set_corner(creased.face(1)[2], 1.0, int(creased.n_vertices()));
  for (const CovarianceMesh& sample :
       {make_sample("icosphere", 320), make_sample("cube"), make_sample("torus"), creased}) {
    const CovarianceMesh mesh = with_covariance(sample, 0.02 * Mat3::Identity());
    SubdivisionOptions limit;
    limit.scheme = scheme_for(mesh.topology(), PlanOptions{});
    limit.levels = 0;
    limit.limit = true;
    const std::vector<Vec3> shrunk = subdivide_points(mesh, limit);
    const LimitPlacement placed = place_for_limit(mesh, PlanOptions{});
    double offset = 0;
    for (size_t v = 0; v < mesh.n_vertices(); ++v)
      offset = std::max(offset, (placed.mesh.mean(v) - (2 * mesh.mean(v) - shrunk[v])).norm());
    EXPECT_LT(offset, 1e-12 * bounding_box_diagonal(mesh)) << mesh.n_vertices() << " vertices";
    EXPECT_LT(placed.gap_after, placed.gap_before);
    for (size_t v = 0; v < mesh.n_vertices(); ++v) ASSERT_EQ(placed.mesh.covariance(v), mesh.covariance(v));
    EXPECT_EQ(placed.mesh.sharpness.creases.size(), mesh.sharpness.creases.size());
    // No step: the mesh as it was.
    const LimitPlacement none = place_for_limit(mesh, PlanOptions{}, 0);
    EXPECT_EQ(max_offset(none.mesh, mesh), 0.0);
    EXPECT_EQ(none.gap_after, none.gap_before);
  }
}

// The rms angle, in degrees, between the limit surface's normals and the unit sphere's (radial) ones.
double sphere_normal_angle(const TriangleMesh& surface) {
  double sum = 0;
  for (size_t i = 0; i < surface.positions.size(); ++i) {
    const double c = std::abs(surface.normals[i].normalized().dot(surface.positions[i].normalized()));
    const double angle = std::acos(std::min(1.0, c)) * 180 / M_PI;
    sum += angle * angle;
  }
  return std::sqrt(sum / double(surface.positions.size()));
}

TEST(LimitPlacement, ASimplifiedSpheresLimitSurfaceComesBackToTheSphere) {
  // A scanned sphere: the unit icosphere with radial noise of 1 %.
  CovarianceMesh dense = make_sample("icosphere", 5120);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> noise(-0.01, 0.01);
  for (size_t v = 0; v < dense.n_vertices(); ++v) dense.set_mean(v, dense.mean(v).normalized() * (1 + noise(random)));
  SimplifyOptions options;
  options.target_vertices = 150;
  const CovarianceMesh coarse = simplify_mesh(dense, options).mesh;
  const LimitPlacement placed = place_for_limit(coarse, PlanOptions{});
  const LimitTriangles before = limit_surface_triangles(coarse, 6), after = limit_surface_triangles(placed.mesh, 6);
  const DistanceSummary shrunk = distances_to_surface(vertex_means(dense), before.triangles);
  const DistanceSummary back = distances_to_surface(vertex_means(dense), after.triangles);
  EXPECT_LT(back.rms, 0.5 * shrunk.rms) << shrunk.rms << " → " << back.rms;
  // The noise is not made into ripples: the normals turn from the sphere's no more than before (the
  // placement's fixed point, interpolation, turns them more than the shrunk surface does).
  EXPECT_LE(sphere_normal_angle(after.triangles), sphere_normal_angle(before.triangles))
      << sphere_normal_angle(before.triangles) << "° → " << sphere_normal_angle(after.triangles) << "°";
}

}  // namespace
}  // namespace gps
