#include "core/edit/covariance_edit.h"

#include <Eigen/Eigenvalues>
#include <algorithm>

namespace gps {

EllipsoidAxes ellipsoid_axes(const Mat3& covariance) {
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(0.5 * (covariance + covariance.transpose()));
  EllipsoidAxes e;
  e.axes = eig.eigenvectors();
  if (e.axes.determinant() < 0) e.axes.col(2) *= -1.0;
  e.sigmas = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  return e;
}

Mat3 covariance_from_axes(const Mat3& axes, const Vec3& sigmas) {
  const Mat3 c = axes * sigmas.cwiseProduct(sigmas).asDiagonal() * axes.transpose();
  return 0.5 * (c + c.transpose());
}

Mat3 clamp_spd(const Mat3& covariance, const Mat3& fallback, double min_variance, double max_variance) {
  if (!covariance.allFinite()) return fallback;
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(0.5 * (covariance + covariance.transpose()));
  const Vec3 clamped = eig.eigenvalues().cwiseMax(min_variance).cwiseMin(max_variance);
  const Mat3 c = eig.eigenvectors() * clamped.asDiagonal() * eig.eigenvectors().transpose();
  return 0.5 * (c + c.transpose());
}

Mat3 scale_axis(const Mat3& covariance, int axis, double factor) {
  EllipsoidAxes e = ellipsoid_axes(covariance);
  e.sigmas[axis] *= factor;
  return covariance_from_axes(e.axes, e.sigmas);
}

Mat3 rotate_covariance(const Mat3& covariance, const Mat3& rotation) {
  const Mat3 c = rotation * covariance * rotation.transpose();
  return 0.5 * (c + c.transpose());
}

double axis_drag_factor(double handle_distance, double drag_along_axis) {
  if (!(handle_distance > 0)) return 1.0;
  return std::clamp((handle_distance + drag_along_axis) / handle_distance, 1e-3, 1e3);
}

}  // namespace gps
