#include "render/gl/moved_frame.h"

#include <algorithm>
#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>

#include "core/mesh/mesh_connectivity.h"

namespace gps {
namespace {

// Within rounding: a mean to this many frame units (the frame's box has a unit diagonal), a
// covariance entry to this share of the Gaussian's largest variance. Double arithmetic's own error
// of a rotation, scale and translation lies far below both, and no edit a designer makes lies within them.
constexpr double kMeanTolerance = 1e-12;
constexpr double kCovarianceTolerance = 1e-13;
// The means the map is fitted to and first checked on, spread over the vertex numbers.
constexpr size_t kSampled = 32;

bool same_within_rounding(const Vec3& mean, const Mat3& covariance, const Vec3& held_mean, const Mat3& held) {
  const double largest = held.diagonal().cwiseAbs().maxCoeff();
  return (mean - held_mean).cwiseAbs().maxCoeff() <= kMeanTolerance &&
         (covariance - held).cwiseAbs().maxCoeff() <= kCovarianceTolerance * largest;
}

// The frame `frame` moved by the map b = s·Q·a + d of its own coordinates: world points
// centre + unit·rotation·(s·Q·a + d).
NormalisedFrame moved_by(const NormalisedFrame& frame, double s, const Mat3& q, const Vec3& d) {
  NormalisedFrame to;
  to.centre = frame.to_world(glm::dvec3(d.x(), d.y(), d.z()));
  to.unit = frame.unit * s;
  if (q == Mat3::Identity()) {
    to.rotation = frame.rotation;
    return to;
  }
  // Composed turns kept orthonormal (the nearest rotation, from the SVD).
  const Eigen::JacobiSVD<Mat3> svd(Mat3(frame.rotation_matrix() * q), Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Mat3 r = svd.matrixU() * svd.matrixV().transpose();
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k) to.rotation[c][k] = r(k, c);
  return to;
}

// The frame moved by the scale and translation, or failing that the scale, rotation and
// translation, that fit the sampled means best (least squares; Umeyama 1991 for the rotation).
std::vector<NormalisedFrame> candidate_frames(const NormalisedFrame& frame, const FramedGaussians& framed,
                                              const CovarianceMesh& mesh, const std::vector<size_t>& sample) {
  // In the frame, the held means a and the new means b.
  Eigen::Matrix3Xd a(3, sample.size()), b(3, sample.size());
  for (size_t k = 0; k < sample.size(); ++k) {
    a.col(Eigen::Index(k)) = framed.means[sample[k]];
    b.col(Eigen::Index(k)) = frame.mean_in_frame(mesh.mean(sample[k]));
  }
  const Vec3 mean_a = a.rowwise().mean(), mean_b = b.rowwise().mean();
  const Eigen::Matrix3Xd da = a.colwise() - mean_a, db = b.colwise() - mean_b;
  const double spread = da.squaredNorm();
  std::vector<NormalisedFrame> frames;
  if (!(spread > 0.0)) return frames;
  const double s = (da.cwiseProduct(db)).sum() / spread;
  if (s > 0.0 && std::isfinite(s)) frames.push_back(moved_by(frame, s, Mat3::Identity(), mean_b - s * mean_a));
  const Eigen::Matrix4d fitted = Eigen::umeyama(a, b, true);
  const Mat3 scaled = fitted.topLeftCorner<3, 3>();
  const double turned_scale = std::cbrt(scaled.determinant());
  if (turned_scale > 0.0 && std::isfinite(turned_scale))
    frames.push_back(moved_by(frame, turned_scale, scaled / turned_scale, fitted.topRightCorner<3, 1>()));
  return frames;
}

}  // namespace

std::optional<NormalisedFrame> moved_frame(const NormalisedFrame& frame, const FramedGaussians& framed,
                                           const CovarianceMesh& mesh, FramedGaussians& moved) {
  const size_t n = mesh.n_vertices();
  if (n < 2 || framed.n_vertices() != n) return std::nullopt;
  std::vector<size_t> sample;
  const size_t sampled = std::min(n, kSampled);
  for (size_t k = 0; k < sampled; ++k) sample.push_back(k * (n - 1) / (sampled - 1));
  const auto fits_sample = [&](const NormalisedFrame& to) {
    if (to == frame || !std::isfinite(to.unit) || !(to.unit > 0.0)) return false;
    for (const size_t v : sample)
      if (!same_within_rounding(to.mean_in_frame(mesh.mean(v)), to.covariance_in_frame(mesh.covariance(v)),
                                framed.means[v], framed.covariances[v]))
        return false;
    return true;
  };
  const std::vector<NormalisedFrame> candidates = candidate_frames(frame, framed, mesh, sample);
  // The sampled means did not move: not a move (the rotation's fit would find one within rounding).
  if (!candidates.empty() && candidates.front() == frame) return std::nullopt;
  const auto fitting = std::find_if(candidates.begin(), candidates.end(), fits_sample);
  if (fitting == candidates.end()) return std::nullopt;
  const NormalisedFrame to = *fitting;
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
