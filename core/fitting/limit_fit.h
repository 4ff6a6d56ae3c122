#pragma once
// Fitting a covariance mesh's GPS limit surface to points (a dense mesh's vertices): the means and
// covariances move to minimise the squared distances from the points to the limit surface.
#include <cmath>
#include <functional>
#include <optional>
#include <vector>

#include "core/fitting/surface_distance.h"
#include "core/mesh/covariance_mesh.h"
#include "core/plans/planned_surface.h"

namespace gps {

/// One iteration of the fit: the distances from the points to their closest points on the limit surface.
struct FitIteration {
  int iteration = 0;      // 0: before the first step
  DistanceSummary error;  // relative to the points' bounding-box diagonal
  double seconds = 0;     // this iteration's time
  /// The fit's objective (the squared distances, the normal and smoothness terms) per point, square
  /// rooted: a length like the rms distance, which the tolerance measures with it.
  double objective = 0;
  /// Whether this iteration moved the means alone (FitOptions::means_first).
  bool means_only = false;
  /// Whether it ran with the relaxed lower bound on the standard deviations (FitOptions::relaxed_min_sigma).
  bool relaxed = false;
};

/// The covariance smoothness of a fit to points without normals, unless FitOptions says otherwise.
inline constexpr double kPointsCovarianceSmoothness = 1e-4;

struct FitOptions {
  /// The most iterations; by default the fit stops sooner, once converged (`tolerance`).
  int iterations = 100;
  /// Means only, every covariance the same isotropic one: the limit is the linear scheme's, linear in
  /// the means (ordinary subdivision-surface fitting).
  bool plain = false;
  /// Weight of the smoothness term (the Laplacian of the means' changes) against the mean squared distance.
  double smoothness = 1e-5;
  /// The same for the covariances (the Laplacian of the changes of their log-Cholesky precision
  /// parameters, times the squared mean edge length): neighbouring Gaussians change alike, so that a
  /// smooth region stays smooth (ignored by a plain fit). Unset: 0 where the points have normals
  /// (the normal term keeps the surface from facets, and the covariances free fit closer), else
  /// kPointsCovarianceSmoothness.
  std::optional<double> covariance_smoothness;
  /// Weight of the prior that keeps each covariance near its start (the Gaussians at the scale of the
  /// features they model): per vertex, the squared change of its log-Cholesky precision parameters,
  /// each made dimensionless, times the squared mean length of its edges, against the mean squared
  /// distance (0: none; ignored by a plain fit).
  double covariance_prior = 0;
  /// Weight of the normal term: per point with a normal n, the squared sine of the angle between n
  /// and the limit surface's normal m at its closest point (|(I − n nᵀ) m|²), times the squared mean
  /// edge length, against its squared distance. The covariances' freedom then shapes the surface
  /// as the points' surface turns, rather than into facets that pass near the points (0 or no
  /// normals: none; ignored by a plain fit, whose surface is smooth everywhere).
  double normal_weight = 0.001;
  /// Each covariance's standard deviations (the square roots of its eigenvalues) kept between these
  /// multiples of the mean length of its vertex's edges, at the start and after every step (0 and
  /// infinity: unbounded; ignored by a plain fit).
  double min_sigma = 0.35, max_sigma = 1.0;
  /// Once the fit converges with the lower bound at min_sigma, the bound drops to this multiple and the
  /// fit goes on until it converges again (at or above min_sigma: no second stage). The Gaussians first
  /// settle at the scale of their edges, then narrow only where the points ask for it (a thin part's
  /// rims, a machined part's edges); narrowed from the start, they sharpen toward the first, far
  /// closest points and settle in a worse fit.
  double relaxed_min_sigma = 0.1;
  /// Stop when an iteration lowers both the rms distance and the objective (FitIteration::objective)
  /// by less than this fraction of each (0: never): by default at 1 %, where further iterations
  /// polish what is already fitted.
  double tolerance = 0.01;
  /// A GPS fit moves the means alone, the covariances held, until an iteration lowers the rms
  /// distance by no more than this fraction of it; then both (0: both from the start). From a start
  /// far from the points, the covariances would otherwise bend toward the first, far closest points
  /// (thin flaps where a plain fit recovers). The tolerance is not checked before both move.
  double means_first = 0.3;
  /// Stop when the fit has run this many seconds (checked after each iteration; infinity: never).
  double time_budget = INFINITY;
  /// Tessellation level of the limit surface that the closest points are first found on.
  int correspondence_level = 6;
  PlanOptions plans;
  /// Called after every iteration, and once before the first.
  std::function<void(const FitIteration&)> progress;
};

/// Why the fit stopped.
enum class FitStop {
  iterations,  // it ran the iterations asked for
  converged,   // the rms distance and the objective fell by less than the tolerance
  time,        // the time budget ran out
  no_descent,  // no step lowered the objective
};

/// Whether a fit relaxes its lower bound once it converges (FitOptions::relaxed_min_sigma).
bool fits_in_two_stages(const FitOptions& options);

/// A few words for a stop reason ("converged", …).
const char* describe(FitStop stop);

struct FitResult {
  CovarianceMesh mesh;
  std::vector<FitIteration> iterations;  // iteration 0 first
  FitStop stop = FitStop::iterations;
};

/// Fits the limit surface of `coarse` to `targets` by Levenberg-Marquardt on the squared distances
/// from each target to its closest limit point (patch, u, v), found again after every accepted step
/// and kept where the old one is closer (with normals, where its distance and normal residual are
/// smaller: the objective never rises), plus the normal term and small smoothness terms.
/// Unknowns per vertex: its mean, and (unless plain) the Cholesky factor L of its precision Σ⁻¹ = LLᵀ
/// with a logarithmic diagonal, positive definite by construction. The limit point is
/// x = K⁻¹h with K = Σₖ wₖ Kₖ, h = Σₖ wₖ Kₖ μₖ over the control vertices (core/fitting/limit_weights.h),
/// whose derivatives are dx = K⁻¹ (dh − dK x); the normal's come from x_u = K⁻¹ (h_u − K_u x).
/// The normal equations are solved by conjugate gradients (Eigen).
/// It stops early where `options` asks (tolerance, time budget) or where no step lowers the objective.
/// On all cores, the same result on any number. Throws gps::Error for a mesh or points it cannot fit.
/// `normals`: the targets' unit normals (empty: none; a zero normal: none at that point), for the
/// normal term of FitOptions::normal_weight.
FitResult fit_limit_surface(const CovarianceMesh& coarse, const std::vector<Vec3>& targets, const FitOptions& options,
                            const std::vector<Vec3>& normals = {});

/// The same mesh with every covariance the isotropic Σ = (σ² I), σ half the mean edge length: the
/// starting point of a plain fit, whose limit surface is the linear scheme's.
CovarianceMesh with_isotropic_covariances(const CovarianceMesh& mesh);

}  // namespace gps
