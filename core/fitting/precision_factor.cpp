#include "core/fitting/precision_factor.h"

#include <cmath>

#include <Eigen/Cholesky>

namespace gps {

Mat3 cholesky_factor(const Vec6& t) {
  Mat3 l = Mat3::Zero();
  for (int c = 0; c < 6; ++c) {
    const int a = kFactorEntries[c][0], b = kFactorEntries[c][1];
    l(a, b) = a == b ? std::exp(t[c]) : t[c];
  }
  return l;
}

Vec6 factor_parameters(const Mat3& precision) {
  const Mat3 l = Eigen::LLT<Mat3>(precision).matrixL();
  Vec6 t;
  for (int c = 0; c < 6; ++c) {
    const int a = kFactorEntries[c][0], b = kFactorEntries[c][1];
    t[c] = a == b ? std::log(l(a, b)) : l(a, b);
  }
  return t;
}

Eigen::Matrix<double, 3, 6> precision_derivatives_times(const Mat3& l, const Vec3& d) {
  Eigen::Matrix<double, 3, 6> out;
  const Vec3 ltd = l.transpose() * d;
  for (int c = 0; c < 6; ++c) {
    const int a = kFactorEntries[c][0], b = kFactorEntries[c][1];
    const double scale = a == b ? l(a, a) : 1.0;
    // dK = dL Lᵀ + L dLᵀ with dL = scale · e_a e_bᵀ: dK d = scale (e_a (Lᵀd)_b + L_{:,b} d_a).
    Vec3 col = scale * d[a] * l.col(b);
    col[a] += scale * ltd[b];
    out.col(c) = col;
  }
  return out;
}

}  // namespace gps
