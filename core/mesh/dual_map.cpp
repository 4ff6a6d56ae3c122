#include "core/mesh/dual_map.h"

#include <Eigen/Cholesky>

namespace gps {

Eigen::Matrix<double, 6, 1> vech(const Mat3& m) {
  Eigen::Matrix<double, 6, 1> v;
  v << m(0, 0), m(0, 1), m(0, 2), m(1, 1), m(1, 2), m(2, 2);
  return v;
}

Mat3 unvech(const Dual& q) {
  Mat3 m;
  m << q[0], q[1], q[2],  //
      q[1], q[3], q[4],   //
      q[2], q[4], q[5];
  return m;
}

Dual to_dual(const Vec3& mean, const Mat3& covariance) {
  const Eigen::LLT<Mat3> llt(covariance);
  const Mat3 precision = llt.solve(Mat3::Identity());
  Dual q;
  q.head<6>() = vech(0.5 * (precision + precision.transpose()));
  q.tail<3>() = llt.solve(mean);
  return q;
}

std::optional<Gaussian> from_dual(const Dual& q) {
  const Eigen::LLT<Mat3> llt(unvech(q));
  if (llt.info() != Eigen::Success) return std::nullopt;
  Gaussian g;
  g.mean = llt.solve(Vec3(q.tail<3>()));
  const Mat3 cov = llt.solve(Mat3::Identity());
  g.covariance = 0.5 * (cov + cov.transpose());
  return g;
}

std::optional<Vec3> mean_from_dual(const Dual& q) {
  const Eigen::LLT<Mat3> llt(unvech(q));
  if (llt.info() != Eigen::Success) return std::nullopt;
  return Vec3(llt.solve(Vec3(q.tail<3>())));
}

Vec3 mean_derivative(const Dual& q, const Dual& q_u, const Vec3& mean) {
  const Eigen::LLT<Mat3> llt(unvech(q));
  return llt.solve(Vec3(q_u.tail<3>()) - unvech(q_u) * mean);
}

bool is_positive_definite(const Dual& q) {
  const Eigen::LLT<Mat3> llt(unvech(q));
  return llt.info() == Eigen::Success;
}

}  // namespace gps
