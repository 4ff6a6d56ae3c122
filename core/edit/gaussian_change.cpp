#include "core/edit/gaussian_change.h"

#include <cmath>

namespace gps {

Mat3 GaussianChange::linear() const {
  const Mat3 s = scale_axis.isZero() ? Mat3(scale * Mat3::Identity())
                                     : Mat3(Mat3::Identity() + (scale - 1.0) * scale_axis * scale_axis.transpose());
  return rotation.toRotationMatrix() * s;
}

Mat3 GaussianChange::apply_to_covariance(const Mat3& covariance) const {
  const Mat3 a = linear();
  const Mat3 c = a * covariance * a.transpose();
  return 0.5 * (c + c.transpose());
}

GaussianChange GaussianChange::weighted(double w) const {
  GaussianChange c = *this;
  c.translation = w * translation;
  c.rotation = Eigen::Quaterniond::Identity().slerp(w, rotation);
  c.scale = std::pow(scale, w);
  return c;
}

GaussianChange GaussianChange::mirrored(int axis) const {
  Mat3 m = Mat3::Identity();
  m(axis, axis) = -1.0;
  GaussianChange c = *this;
  c.translation = m * translation;
  c.rotation = Eigen::Quaterniond(Mat3(m * rotation.toRotationMatrix() * m));
  c.scale_axis = m * scale_axis;
  return c;
}

}  // namespace gps
