// How well a GPS limit surface fits: a block with sharp edges, a bumpy sphere and a noisy one,
// simplified and fitted (plain and GPS) against the simplified mesh's own triangles; a smooth
// sphere's normals and the Gaussians' bounds; a thin part's rims once the bound is relaxed; the
// normal term's turning of the surface.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <cstdio>

#include "core/fitting/face_triangles.h"
#include "core/fitting/limit_fit.h"
#include "core/fitting/mesh_simplification.h"
#include "core/fitting/surface_distance.h"
#include "tests/support/fit_cases.h"

namespace gps {
namespace {

using test::block;
using test::bumpy_sphere;
using test::cube_surface;
using test::expect_same_gaussians;
using test::mean_edge_lengths;

struct FitFigures {
  double simplified = 0, plain = 0, gps = 0;  // rms over the diagonal
};

FitResult fit(const CovarianceMesh& coarse, const std::vector<Vec3>& targets, bool plain,
              const std::vector<Vec3>& normals = {}) {
  FitOptions options;
  options.iterations = 8;
  options.plain = plain;
  FitResult r = fit_limit_surface(coarse, targets, options, normals);
  for (size_t k = 1; k < r.iterations.size(); ++k)
    EXPECT_LE(r.iterations[k].error.rms, r.iterations[k - 1].error.rms * (1 + 1e-9)) << "iteration " << k;
  EXPECT_LT(r.iterations.back().error.rms, r.iterations.front().error.rms);
  for (size_t i = 0; i < r.mesh.n_vertices(); ++i) EXPECT_TRUE(is_spd(r.mesh.covariance(i))) << "vertex " << i;
  return r;
}

FitFigures fit_figures(const CovarianceMesh& dense, size_t vertices) {
  SimplifyOptions s;
  s.target_vertices = vertices;
  const CovarianceMesh coarse = simplify_mesh(dense, s).mesh;
  const std::vector<Vec3> targets = vertex_means(dense);
  const auto measured = [&](const CovarianceMesh& m) {
    return distances_to_surface(targets, limit_surface_triangles(m, 6).triangles).relative_rms();
  };
  FitFigures f;
  f.simplified = distances_to_surface(targets, face_triangles(coarse)).relative_rms();
  f.plain = measured(fit(coarse, targets, true).mesh);
  f.gps = measured(fit(coarse, targets, false).mesh);
  std::printf("simplified %.3e, plain fit %.3e, GPS fit %.3e (rms over the diagonal)\n", f.simplified, f.plain, f.gps);
  return f;
}

TEST(LimitFit, BlockWithSharpEdges) {
  // The block's faces are flat, so the simplified mesh itself is exact; a smooth limit surface rounds
  // its edges, the GPS limit much less than the plain one.
  const FitFigures f = fit_figures(block(16), 200);
  EXPECT_LT(f.gps, 0.5 * f.plain);
}

TEST(LimitFit, BumpySphere) {
  const FitFigures f = fit_figures(bumpy_sphere(16), 200);
  EXPECT_LT(f.gps, 0.8 * f.plain);
  EXPECT_LT(f.plain, f.simplified);
  EXPECT_LT(f.gps, 0.5 * f.simplified);
}

TEST(LimitFit, NoisyScan) {
  const FitFigures f = fit_figures(bumpy_sphere(16, 0.003), 200);
  EXPECT_LT(f.gps, 0.8 * f.plain);
  EXPECT_LT(f.gps, f.simplified);
}

TEST(LimitFit, SmoothSphereTurnsNoFurtherThanThePlainFitAndKeepsItsGaussiansToTheEdges) {
  const CovarianceMesh dense = cube_surface(12, [](const Vec3& p) { return Vec3(p.normalized()); });
  SimplifyOptions s;
  s.target_vertices = 120;
  const CovarianceMesh coarse = simplify_mesh(dense, s).mesh;
  const TriangleMesh scan = face_triangles(dense);
  const auto normals_rms = [&](const CovarianceMesh& m) {
    const TriangleMesh limit = limit_surface_triangles(m, 6).triangles;
    return summarise_angles(SurfaceDistance(limit).normal_angles(scan.positions, scan.normals)).rms;
  };
  const FitResult gps = fit(coarse, scan.positions, false, smooth_vertex_normals(scan));
  const double plain = normals_rms(fit(coarse, scan.positions, true).mesh), turned = normals_rms(gps.mesh);
  std::printf("normals' rms angle: plain fit %.3f°, GPS fit %.3f°\n", plain, turned);
  EXPECT_LE(turned, plain);
  // Every standard deviation within FitOptions' bounds times the mean length of its vertex's edges.
  const FitOptions defaults;
  const std::vector<double> edge = mean_edge_lengths(coarse);
  for (size_t i = 0; i < coarse.n_vertices(); ++i) {
    const Vec3 variances = Eigen::SelfAdjointEigenSolver<Mat3>(gps.mesh.covariance(i)).eigenvalues();
    EXPECT_LE(std::sqrt(variances.maxCoeff()), defaults.max_sigma * edge[i] * (1 + 1e-9)) << "vertex " << i;
    EXPECT_GE(std::sqrt(variances.minCoeff()), defaults.relaxed_min_sigma * edge[i] * (1 - 1e-9)) << "vertex " << i;
  }
}

TEST(LimitFit, AThinPartsRimsFitCloserOnceTheLowerBoundIsRelaxed) {
  // A flat ellipsoid thinner than its simplified mesh's edges are long, like a turbine blade: with
  // each σ at least 0.35 of its vertex's mean edge, the rims stay too round; relaxed once the fit has
  // converged, the Gaussians there narrow.
  const CovarianceMesh dense =
      cube_surface(16, [](const Vec3& p) { return Vec3(p.normalized().cwiseProduct(Vec3(2.0, 1.0, 0.06))); });
  SimplifyOptions s;
  s.target_vertices = 200;
  const CovarianceMesh coarse = simplify_mesh(dense, s).mesh;
  const TriangleMesh scan = face_triangles(dense);
  const std::vector<Vec3> normals = smooth_vertex_normals(scan);
  const auto rms = [&](const FitOptions& options) {
    const FitResult r = fit_limit_surface(coarse, scan.positions, options, normals);
    return distances_to_surface(scan.positions, limit_surface_triangles(r.mesh, 6).triangles).relative_rms();
  };
  FitOptions one_stage, plain;
  one_stage.relaxed_min_sigma = one_stage.min_sigma;
  plain.plain = true;
  const double relaxed = rms(FitOptions()), first = rms(one_stage), smooth = rms(plain);
  std::printf("rms over the diagonal: plain %.3e, one stage %.3e, relaxed %.3e\n", smooth, first, relaxed);
  EXPECT_LT(relaxed, 0.9 * first);
  EXPECT_LT(relaxed, 0.8 * smooth);
}

/// A bumpy sphere's vertices with their normals, and a simplified mesh to fit to them.
struct ScanToFit {
  std::vector<Vec3> points, normals;
  CovarianceMesh coarse;
};

ScanToFit bumpy_scan() {
  const CovarianceMesh dense = bumpy_sphere(16);
  SimplifyOptions s;
  s.target_vertices = 200;
  const TriangleMesh scan = face_triangles(dense);
  return {scan.positions, smooth_vertex_normals(scan), simplify_mesh(dense, s).mesh};
}

TEST(LimitFit, TheNormalTermTurnsTheSurfaceAsTheScanTurnsAndTheObjectiveNeverRises) {
  const ScanToFit scan = bumpy_scan();
  const auto fitted = [&](double normal_weight) {
    FitOptions options;
    options.iterations = 8;
    options.tolerance = 0;
    options.covariance_smoothness = 0;  // the same for both: only the normal term differs
    options.normal_weight = normal_weight;
    const FitResult r = fit_limit_surface(scan.coarse, scan.points, options, scan.normals);
    // The old closest point is kept where its distance and normal residual are smaller, so no
    // iteration raises the objective.
    for (size_t k = 1; k < r.iterations.size(); ++k)
      EXPECT_LE(r.iterations[k].objective, r.iterations[k - 1].objective * (1 + 1e-12)) << "iteration " << k;
    const TriangleMesh limit = limit_surface_triangles(r.mesh, 6).triangles;
    const SurfaceDistance surface(limit);
    const double angle = summarise_angles(surface.normal_angles(scan.points, scan.normals)).rms;
    const double rms = summarise_distances(surface.distances(scan.points), 1).rms;
    std::printf("normal weight %g: rms %.3e, normals' rms angle %.3f°\n", normal_weight, rms, angle);
    return std::pair(rms, angle);
  };
  const auto [free_rms, free_angle] = fitted(0);
  const auto [turned_rms, turned_angle] = fitted(FitOptions().normal_weight);
  const auto [strong_rms, strong_angle] = fitted(0.5);
  EXPECT_LT(turned_angle, free_angle);
  EXPECT_LT(strong_angle, turned_angle);
  EXPECT_LT(turned_rms, 1.5 * free_rms);
  EXPECT_GT(strong_rms, free_rms);  // a strong normal term trades distance for turning
}

TEST(LimitFit, NormalsChangeNothingWhereTheTermCannotUseThem) {
  const ScanToFit scan = bumpy_scan();
  FitOptions options;
  options.iterations = 2;
  options.covariance_smoothness = kPointsCovarianceSmoothness;
  const FitResult without = fit_limit_surface(scan.coarse, scan.points, options);
  // Zero normals, or a weight of 0, are no normals.
  expect_same_gaussians(
      without.mesh,
      fit_limit_surface(scan.coarse, scan.points, options, std::vector<Vec3>(scan.points.size(), Vec3::Zero())).mesh);
  FitOptions weightless = options;
  weightless.normal_weight = 0;
  expect_same_gaussians(without.mesh, fit_limit_surface(scan.coarse, scan.points, weightless, scan.normals).mesh);
  EXPECT_FALSE(fit_limit_surface(scan.coarse, scan.points, options, scan.normals).mesh.means() == without.mesh.means());
  // A plain fit's surface is smooth everywhere: it takes no normal term.
  FitOptions plain = options;
  plain.plain = true;
  expect_same_gaussians(fit_limit_surface(scan.coarse, scan.points, plain).mesh,
                        fit_limit_surface(scan.coarse, scan.points, plain, scan.normals).mesh);
  // Unset, the covariance smoothness is 0 with normals and kPointsCovarianceSmoothness without.
  FitOptions unset = options;
  unset.covariance_smoothness.reset();
  expect_same_gaussians(without.mesh, fit_limit_surface(scan.coarse, scan.points, unset).mesh);
  FitOptions zero = options;
  zero.covariance_smoothness = 0;
  expect_same_gaussians(fit_limit_surface(scan.coarse, scan.points, zero, scan.normals).mesh,
                        fit_limit_surface(scan.coarse, scan.points, unset, scan.normals).mesh);
}

}  // namespace
}  // namespace gps
