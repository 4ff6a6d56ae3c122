#pragma once
// A precision K = Σ⁻¹ as six unconstrained parameters: the entries of its Cholesky factor L (K = LLᵀ,
// L lower-triangular) with the diagonal ones as logarithms, so that every parameter vector gives a
// positive definite K (the log-Cholesky parameterisation the fit moves).
#include <Eigen/Core>

#include "core/mesh/linalg.h"

namespace gps {

using Vec6 = Eigen::Matrix<double, 6, 1>;

/// The lower-triangular entries (row, column) of L that the six parameters set, in order; the
/// diagonal ones through exp.
inline constexpr int kFactorEntries[6][2] = {{0, 0}, {1, 0}, {1, 1}, {2, 0}, {2, 1}, {2, 2}};

/// L for the parameters t.
Mat3 cholesky_factor(const Vec6& t);
/// The parameters of a symmetric positive definite precision.
Vec6 factor_parameters(const Mat3& precision);
/// Column c: dK/dθ_c · d for the precision K = LLᵀ and its parameter θ_c.
Eigen::Matrix<double, 3, 6> precision_derivatives_times(const Mat3& l, const Vec3& d);

}  // namespace gps
