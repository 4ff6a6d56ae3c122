#include "render/gl/moved_frame.h"

#include <algorithm>
#include <cmath>

#include "core/mesh/mesh_connectivity.h"

namespace gps {
namespace {

// Within rounding: a mean to this many frame units (the frame's box has a unit diagonal), a
// covariance entry to this share of the Gaussian's largest variance. Double arithmetic's own error
// of a scale and a translation lies far below both, and no edit a designer makes lies within them.
constexpr double kMeanTolerance = 1e-12;
constexpr double kCovarianceTolerance = 1e-13;
// The means the map is fitted to and first checked on, spread over the vertex numbers.
constexpr size_t kSampled = 32;

bool same_within_rounding(const Vec3& mean, const Mat3& covariance, const Vec3& held_mean, const Mat3& held) {
  const double largest = held.diagonal().cwiseAbs().maxCoeff();
  return (mean - held_mean).cwiseAbs().maxCoeff() <= kMeanTolerance &&
         (covariance - held).cwiseAbs().maxCoeff() <= kCovarianceTolerance * largest;
}

}  // namespace

std::optional<NormalisedFrame> moved_frame(const NormalisedFrame& frame, const FramedGaussians& framed,
                                           const CovarianceMesh& mesh, FramedGaussians& moved) {
  const size_t n = mesh.n_vertices();
  if (n < 2 || framed.n_vertices() != n) return std::nullopt;
  std::vector<size_t> sample;
  const size_t sampled = std::min(n, kSampled);
  for (size_t k = 0; k < sampled; ++k) sample.push_back(k * (n - 1) / (sampled - 1));
  // In the frame, the held means a and the new means b; b = s·a + d fitted by least squares.
  Vec3 mean_a = Vec3::Zero(), mean_b = Vec3::Zero();
  for (const size_t v : sample) mean_a += framed.means[v], mean_b += frame.mean_in_frame(mesh.mean(v));
  mean_a /= double(sampled), mean_b /= double(sampled);
  double along = 0.0, spread = 0.0;
  for (const size_t v : sample) {
    const Vec3 a = framed.means[v] - mean_a;
    along += a.dot(frame.mean_in_frame(mesh.mean(v)) - mean_b);
    spread += a.squaredNorm();
  }
  const double s = along / spread;
  if (!(spread > 0.0) || !(s > 0.0) || !std::isfinite(s)) return std::nullopt;
  const Vec3 d = mean_b - s * mean_a;
  NormalisedFrame to;
  to.centre = frame.to_world(glm::dvec3(d.x(), d.y(), d.z()));
  to.unit = frame.unit * s;
  if (to == frame || !std::isfinite(to.unit) || !(to.unit > 0.0)) return std::nullopt;
  for (const size_t v : sample)
    if (!same_within_rounding(to.mean_in_frame(mesh.mean(v)), to.covariance_in_frame(mesh.covariance(v)),
                              framed.means[v], framed.covariances[v]))
      return std::nullopt;
  moved.means.resize(n);
  moved.covariances.resize(n);
  // Framed and checked on all cores.
  bool same = true;
#pragma omp parallel for schedule(static) reduction(&& : same) if (n >= size_t(kParallelFaces))
  for (size_t v = 0; v < n; ++v) {
    moved.means[v] = to.mean_in_frame(mesh.mean(v));
    moved.covariances[v] = to.covariance_in_frame(mesh.covariance(v));
    same = same && same_within_rounding(moved.means[v], moved.covariances[v], framed.means[v], framed.covariances[v]);
  }
  if (!same) return std::nullopt;
  return to;
}

}  // namespace gps
