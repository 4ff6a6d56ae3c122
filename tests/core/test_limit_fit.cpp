// Fitting a GPS limit surface to points: the limit weights against the evaluator, and how a fit runs:
// the same on any number of threads, its stops (tolerance, time budget), the lower bound relaxed once
// converged, the means moved first, the covariance prior and the refusals. How well fits fit is
// tests/numeric/test_limit_fit_quality.cpp's.
#include <gtest/gtest.h>

#include <omp.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <random>

#include "core/evaluation/patch_eval.h"
#include "core/fitting/closest_points.h"
#include "core/fitting/face_triangles.h"
#include "core/fitting/limit_fit.h"
#include "core/fitting/limit_weights.h"
#include "core/fitting/mesh_simplification.h"
#include "core/fitting/surface_distance.h"
#include "core/mesh/dual_map.h"
#include "core/modelling/samples.h"
#include "core/plans/stencil_table.h"
#include "tests/support/fit_cases.h"

namespace gps {
namespace {

using test::block;
using test::bumpy_sphere;
using test::expect_same_gaussians;
using test::mean_edge_lengths;

/// Random Gaussians on a mesh's vertices: means as they are, random SPD covariances.
CovarianceMesh with_random_gaussians(CovarianceMesh m) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (size_t i = 0; i < m.n_vertices(); ++i) {
    Mat3 a;
    for (int k = 0; k < 9; ++k) a(k / 3, k % 3) = u(random);
    m.set_covariance(i, 0.01 * (a * a.transpose() + 0.2 * Mat3::Identity()));
  }
  return m;
}

void expect_weights_match_evaluator(const CovarianceMesh& m) {
  const PlannedSurface surface(m, {});
  const PatchPlans& plans = surface.tables().plans;
  const std::vector<Dual> base = base_points(m);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int trial = 0; trial < 400; ++trial) {
    const int patch = int(random() % unsigned(plans.n_patches()));
    // Half of the samples close to a corner, where extraordinary nodes step past their tables.
    double u = unit(random), v = unit(random);
    if (trial % 2) u *= 1e-3, v *= 1e-3;
    clamp_to_patch(plans.shape, u, v);
    Dual q, q_u, q_v, w, w_u, w_v;
    evaluate_dual(plans, surface.points(), patch, u, v, q, q_u, q_v);
    const LimitWeights weights = limit_weights(plans, surface.tables().stencils, patch, u, v);
    apply_limit_weights(weights, base, w, w_u, w_v);
    double sum = 0;
    for (const double x : weights.value) sum += x;
    EXPECT_NEAR(sum, 1.0, 1e-12);
    const double scale = q.cwiseAbs().maxCoeff();
    EXPECT_LT((w - q).cwiseAbs().maxCoeff(), 1e-12 * scale) << "patch " << patch << " at " << u << ", " << v;
    EXPECT_LT((w_u - q_u).cwiseAbs().maxCoeff(), 1e-10 * scale);
    EXPECT_LT((w_v - q_v).cwiseAbs().maxCoeff(), 1e-10 * scale);
  }
}

TEST(LimitWeights, LoopMatchesTheEvaluator) {
  expect_weights_match_evaluator(with_random_gaussians(make_sample("icosphere", 320)));
}

TEST(LimitWeights, CatmullClarkMatchesTheEvaluator) {
  expect_weights_match_evaluator(with_random_gaussians(make_sample("valence5")));
  expect_weights_match_evaluator(with_random_gaussians(make_sample("cylinder")));
}

TEST(LimitFit, SameResultOnOneAndTwoThreads) {
  const CovarianceMesh dense = bumpy_sphere(10);
  SimplifyOptions s;
  s.target_vertices = 100;
  const CovarianceMesh coarse = simplify_mesh(dense, s).mesh;
  FitOptions options;
  options.iterations = 3;
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const FitResult one = fit_limit_surface(coarse, vertex_means(dense), options);
  omp_set_num_threads(2);
  const FitResult two = fit_limit_surface(coarse, vertex_means(dense), options);
  omp_set_num_threads(threads);
  for (size_t i = 0; i < coarse.n_vertices(); ++i) {
    EXPECT_EQ(one.mesh.mean(i), two.mesh.mean(i)) << "vertex " << i;
    EXPECT_EQ(one.mesh.covariance(i), two.mesh.covariance(i)) << "vertex " << i;
  }
}

TEST(LimitFit, PointsOnTheStartingSurfaceStayPut) {
  // Targets sampled from the coarse mesh's own limit surface: the start fits them already.
  const CovarianceMesh coarse = with_random_gaussians(make_sample("icosphere", 80));
  const std::vector<Vec3> targets = limit_surface_triangles(coarse, 4).triangles.positions;
  FitOptions options;
  options.iterations = 2;
  options.min_sigma = 0;  // the random Gaussians as they are: bounds would move the start off the targets
  options.max_sigma = INFINITY;
  const FitResult r = fit_limit_surface(coarse, targets, options);
  EXPECT_LT(r.iterations.front().error.relative_max(), 1e-9);
  EXPECT_LT(r.iterations.back().error.relative_max(), 1e-9);
}

/// An icosphere fitted to a bumpy sphere's points: a fit whose error levels off within tens of
/// iterations, in one stage (its lower bound never relaxed: FitOptions::relaxed_min_sigma).
FitResult fit_icosphere_to_bumps(int iterations, double tolerance, double time_budget = INFINITY) {
  FitOptions options;
  options.iterations = iterations;
  options.tolerance = tolerance;
  options.time_budget = time_budget;
  options.relaxed_min_sigma = options.min_sigma;
  return fit_limit_surface(make_sample("icosphere", 80), vertex_means(bumpy_sphere(8)), options);
}

/// The larger of the rms distance's and the objective's fall at iteration k, a fraction of each.
double fall_at(const FitResult& r, size_t k) {
  const FitIteration &before = r.iterations[k - 1], &now = r.iterations[k];
  return std::max(1 - now.error.rms / before.error.rms, 1 - now.objective / before.objective);
}

TEST(LimitFit, StopsWhenTheErrorFallsByLessThanTheTolerance) {
  const double tolerance = 0.05;
  const FitResult r = fit_icosphere_to_bumps(40, tolerance);
  EXPECT_EQ(r.stop, FitStop::converged);
  ASSERT_GE(r.iterations.size(), 3u);
  ASSERT_LT(r.iterations.size(), 41u);
  // It stops at the first iteration where both the rms distance and the objective fall by no more.
  EXPECT_LE(fall_at(r, r.iterations.size() - 1), tolerance);
  for (size_t k = 1; k + 1 < r.iterations.size(); ++k) EXPECT_GT(fall_at(r, k), tolerance) << "iteration " << k;
  for (const FitIteration& it : r.iterations) EXPECT_FALSE(it.relaxed);
  // Stopping changes nothing of the iterations run: the same mesh as a fit asked for that many.
  expect_same_gaussians(r.mesh, fit_icosphere_to_bumps(int(r.iterations.size()) - 1, 0).mesh);
}

TEST(LimitFit, OnceConvergedItRelaxesTheLowerBoundAndGoesOnUntilItConvergesAgain) {
  // An icosphere fitted to an ellipsoid 0.3 as thick as it is wide, whose rims want narrower Gaussians.
  const CovarianceMesh coarse = make_sample("icosphere", 80);
  const std::vector<Vec3> targets = vertex_means(
      test::cube_surface(8, [](const Vec3& p) { return Vec3(p.normalized().cwiseProduct(Vec3(1, 1, 0.3))); }));
  const double tolerance = 0.02;
  const auto fitted = [&](bool two_stages) {
    FitOptions options;
    options.iterations = 60;
    options.tolerance = tolerance;
    if (!two_stages) options.relaxed_min_sigma = options.min_sigma;
    return fit_limit_surface(coarse, targets, options);
  };
  const FitResult r = fitted(true);
  EXPECT_EQ(r.stop, FitStop::converged);
  size_t relaxed = 1;  // the first iteration at the relaxed bound
  while (relaxed < r.iterations.size() && !r.iterations[relaxed].relaxed) ++relaxed;
  ASSERT_LT(relaxed, r.iterations.size());
  ASSERT_GE(relaxed, 3u);
  // The first stage ran as a one-stage fit does, iteration for iteration, to its convergence.
  const FitResult first = fitted(false);
  ASSERT_EQ(first.iterations.size(), relaxed);
  for (size_t k = 0; k < relaxed; ++k) EXPECT_EQ(r.iterations[k].error.rms, first.iterations[k].error.rms) << k;
  // Then every iteration is relaxed, and the second stage stops at its own first small fall.
  for (size_t k = relaxed; k < r.iterations.size(); ++k) EXPECT_TRUE(r.iterations[k].relaxed) << k;
  for (size_t k = relaxed; k + 1 < r.iterations.size(); ++k) EXPECT_GT(fall_at(r, k), tolerance) << "iteration " << k;
  EXPECT_LE(fall_at(r, r.iterations.size() - 1), tolerance);
  EXPECT_LT(r.iterations.back().error.rms, first.iterations.back().error.rms);
  // Its standard deviations within the relaxed bound, some below the first.
  const FitOptions defaults;
  const std::vector<double> edge = mean_edge_lengths(coarse);
  bool narrowed = false;
  for (size_t i = 0; i < r.mesh.n_vertices(); ++i) {
    const double least = std::sqrt(Eigen::SelfAdjointEigenSolver<Mat3>(r.mesh.covariance(i)).eigenvalues()[0]);
    EXPECT_GE(least, defaults.relaxed_min_sigma * edge[i] * (1 - 1e-9)) << "vertex " << i;
    narrowed = narrowed || least < defaults.min_sigma * edge[i] * (1 - 1e-9);
  }
  EXPECT_TRUE(narrowed);
}

TEST(LimitFit, ToleranceZeroRunsEveryIteration) {
  const FitResult converged = fit_icosphere_to_bumps(40, 0.05);
  const int iterations = int(converged.iterations.size()) + 2;
  const FitResult r = fit_icosphere_to_bumps(iterations, 0);
  EXPECT_EQ(r.stop, FitStop::iterations);
  EXPECT_EQ(r.iterations.size(), size_t(iterations) + 1);
  // An unlimited time budget is the default's: bit for bit the same fit.
  FitOptions options;
  options.iterations = iterations;
  expect_same_gaussians(r.mesh,
                        fit_limit_surface(make_sample("icosphere", 80), vertex_means(bumpy_sphere(8)), options).mesh);
}

TEST(LimitFit, StopsWhenTheTimeBudgetRunsOut) {
  const FitResult r = fit_icosphere_to_bumps(10, 0, 1e-9);
  EXPECT_EQ(r.stop, FitStop::time);
  EXPECT_EQ(r.iterations.size(), 2u);  // the start and the one iteration before the budget is checked
  expect_same_gaussians(r.mesh, fit_icosphere_to_bumps(1, 0).mesh);
}

TEST(LimitFit, AGpsFitMovesItsMeansAloneUntilTheirFallSlows) {
  const CovarianceMesh coarse = make_sample("icosphere", 80);
  const std::vector<Vec3> targets = vertex_means(bumpy_sphere(8));
  const auto fitted = [&](int iterations, double means_first) {
    FitOptions options;
    options.iterations = iterations;
    options.tolerance = 0;
    options.means_first = means_first;
    return fit_limit_surface(coarse, targets, options);
  };
  const FitResult start = fitted(0, 0.3), first = fitted(1, 0.3), free = fitted(1, 0);
  ASSERT_EQ(first.iterations.size(), 2u);
  EXPECT_TRUE(first.iterations[1].means_only);
  EXPECT_FALSE(free.iterations[1].means_only);
  for (size_t i = 0; i < coarse.n_vertices(); ++i) {
    EXPECT_EQ(first.mesh.covariance(i), start.mesh.covariance(i)) << "vertex " << i;  // held (bounds applied)
    EXPECT_NE(first.mesh.mean(i), start.mesh.mean(i)) << "vertex " << i;
  }
  bool moved = false;
  for (size_t i = 0; i < coarse.n_vertices(); ++i) moved = moved || free.mesh.covariance(i) != start.mesh.covariance(i);
  EXPECT_TRUE(moved);
  // The covariances move once an iteration lowers the rms distance by no more than the fraction.
  const FitResult r = fitted(12, 0.3);
  size_t k = 1;
  while (k < r.iterations.size() && r.iterations[k].means_only) ++k;
  ASSERT_LT(k, r.iterations.size());
  ASSERT_GE(k, 2u);
  // Every means-only iteration but the last lowered the rms by more than the fraction.
  for (size_t j = 1; j + 1 < k; ++j)
    EXPECT_GT(1 - r.iterations[j].error.rms / r.iterations[j - 1].error.rms, 0.3) << "iteration " << j;
  EXPECT_LE(1 - r.iterations[k - 1].error.rms / r.iterations[k - 2].error.rms, 0.3);
}

TEST(LimitFit, RefusesAToleranceOrTimeBudgetOutOfRange) {
  for (const double tolerance : {-0.1, 1.5, double(NAN)}) EXPECT_THROW(fit_icosphere_to_bumps(2, tolerance), Error);
  for (const double budget : {0.0, -1.0, double(NAN)}) EXPECT_THROW(fit_icosphere_to_bumps(2, 0, budget), Error);
}

TEST(LimitFit, TheCovariancePriorHoldsTheGaussiansToTheirStart) {
  // Unbounded, the fit moves the covariances; a strong prior keeps them near the start, means free.
  const CovarianceMesh coarse = make_sample("icosphere", 80);
  const std::vector<Vec3> targets = vertex_means(bumpy_sphere(8));
  const auto largest_change = [&](double prior) {
    FitOptions options;
    options.iterations = 4;
    options.min_sigma = 0;
    options.max_sigma = INFINITY;
    options.covariance_prior = prior;
    const FitResult r = fit_limit_surface(coarse, targets, options);
    EXPECT_LT(r.iterations.back().error.rms, 0.9 * r.iterations.front().error.rms) << "prior " << prior;
    double change = 0;
    for (size_t i = 0; i < coarse.n_vertices(); ++i)
      change = std::max(change, (r.mesh.covariance(i) - coarse.covariance(i)).norm() / coarse.covariance(i).norm());
    return change;
  };
  const double free = largest_change(0), held = largest_change(1e4);
  EXPECT_GT(free, 0.05);
  EXPECT_LT(held, 0.01 * free);
}

TEST(SmoothVertexNormals, AVertexOnASharpEdgeOrCornerHasNone) {
  const TriangleMesh box = face_triangles(block(2));
  const std::vector<Vec3> normals = smooth_vertex_normals(box);
  int interior = 0;
  for (size_t v = 0; v < box.positions.size(); ++v) {
    const Vec3 p = box.positions[v].cwiseQuotient(Vec3(1.0, 0.6, 0.4));
    const int on_faces = int(std::abs(std::abs(p[0]) - 1) < 1e-12) + int(std::abs(std::abs(p[1]) - 1) < 1e-12) +
                         int(std::abs(std::abs(p[2]) - 1) < 1e-12);
    if (on_faces > 1) {
      EXPECT_EQ(normals[v], Vec3::Zero()) << "vertex " << v << " on an edge";
    } else {
      ++interior;
      Eigen::Index axis = 0;
      Vec3(p.cwiseAbs()).maxCoeff(&axis);
      EXPECT_NEAR(normals[v][axis], p[axis] > 0 ? 1.0 : -1.0, 1e-12) << "vertex " << v;
    }
  }
  EXPECT_EQ(interior, 6);  // the middle of each face
  // A wider angle takes the edges' normals too.
  for (const Vec3& n : smooth_vertex_normals(box, 91)) EXPECT_NEAR(n.norm(), 1.0, 1e-12);
}

TEST(LimitFit, RefusesABadCovarianceWeightOrSigmaBounds) {
  const CovarianceMesh coarse = make_sample("icosphere", 80);
  const std::vector<Vec3> targets = vertex_means(coarse);
  for (const auto& [prior, low, high] : std::vector<std::array<double, 3>>{
           {-1, 0.25, 1}, {double(NAN), 0.25, 1}, {INFINITY, 0.25, 1}, {0, -0.1, 1}, {0, 1, 1}, {0, 2, 1}}) {
    FitOptions options;
    options.iterations = 1;
    options.covariance_prior = prior;
    options.min_sigma = low;
    options.max_sigma = high;
    EXPECT_THROW(fit_limit_surface(coarse, targets, options), Error) << prior << " " << low << " " << high;
  }
  for (const double smoothness : {-1.0, double(NAN), double(INFINITY)}) {
    FitOptions options;
    options.covariance_smoothness = smoothness;
    EXPECT_THROW(fit_limit_surface(coarse, targets, options), Error) << smoothness;
    FitOptions normal;
    normal.normal_weight = smoothness;
    EXPECT_THROW(fit_limit_surface(coarse, targets, normal), Error) << smoothness;
  }
  for (const double relaxed : {-0.1, double(NAN), double(INFINITY)}) {
    FitOptions options;
    options.relaxed_min_sigma = relaxed;
    EXPECT_THROW(fit_limit_surface(coarse, targets, options), Error) << relaxed;
  }
  EXPECT_THROW(fit_limit_surface(coarse, targets, FitOptions(), std::vector<Vec3>(targets.size() + 1, Vec3::UnitX())),
               Error);
  // Points farther from the mesh than either is across: a fit would stretch the mesh toward them.
  std::vector<Vec3> far = targets;
  for (Vec3& p : far) p.x() += 1e6;
  try {
    fit_limit_surface(coarse, far, FitOptions());
    ADD_FAILURE() << "fitted to points 1e6 away";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("place the mesh over them first"), std::string::npos) << e.what();
  }
  for (Vec3& p : far) p.x() -= 1e6 - 3;  // moved by 3: a gap of 1 against a size of about 3.5, fitted
  EXPECT_NO_THROW(fit_limit_surface(coarse, far, FitOptions()));
}

}  // namespace
}  // namespace gps
