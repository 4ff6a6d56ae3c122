#pragma once
// The dual map F between a Gaussian (μ, Σ) and its 9D vector q (thesis Eq. 2.10/2.11),
// and the back-transform of tangents (thesis Eq. 3.12).
#include <optional>

#include "core/mesh/linalg.h"

namespace gps {

struct Gaussian {
  Vec3 mean = Vec3::Zero();
  Mat3 covariance = Mat3::Identity();
};

/// vech of a symmetric matrix: (xx, xy, xz, yy, yz, zz).
Eigen::Matrix<double, 6, 1> vech(const Mat3& m);
/// The symmetric matrix [q̂] whose vech is the first six entries of q.
Mat3 unvech(const Dual& q);

/// F(μ, Σ) = (vech(Σ⁻¹), Σ⁻¹μ) (thesis Eq. 2.10). Σ must be symmetric positive definite.
Dual to_dual(const Vec3& mean, const Mat3& covariance);
inline Dual to_dual(const Gaussian& g) { return to_dual(g.mean, g.covariance); }

/// F⁻¹(q): Σ = [q̂]⁻¹, μ solves [q̂] μ = q̄ (thesis Eq. 2.11). Empty when [q̂] is not positive definite.
std::optional<Gaussian> from_dual(const Dual& q);

/// μ alone from q (solves [q̂] μ = q̄ without forming Σ). Empty when [q̂] is not positive definite.
std::optional<Vec3> mean_from_dual(const Dual& q);

/// Tangent of the mean along a parameter: μ_u = [q̂]⁻¹ (q̄_u − [q̂_u] μ) (thesis Eq. 3.12).
Vec3 mean_derivative(const Dual& q, const Dual& q_u, const Vec3& mean);

/// Whether [q̂] is symmetric positive definite (the cone Q_pd of thesis 2.2).
bool is_positive_definite(const Dual& q);

}  // namespace gps
