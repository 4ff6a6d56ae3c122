#pragma once
// One edit of a Gaussian as an affine change: μ' = μ + t, Σ' = A Σ Aᵀ with A = R·S, where R is a
// rotation and S scales along one unit axis u (S = I + (s − 1) u uᵀ) or uniformly (S = s I). A
// scale along a principal axis keeps the frame and the other σ; a rotation keeps every σ. The same
// change can be applied partially (proportional editing) and mirrored (symmetric editing).
#include <Eigen/Geometry>

#include "core/mesh/linalg.h"

namespace gps {

struct GaussianChange {
  Vec3 translation = Vec3::Zero();
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Vec3 scale_axis = Vec3::Zero();  // unit; zero: the scale is uniform
  double scale = 1.0;

  /// Whether Σ' = Σ exactly (no rotation, no scale): a pure move.
  bool keeps_covariance() const { return scale == 1.0 && rotation.coeffs() == Eigen::Quaterniond::Identity().coeffs(); }
  /// A = R·S.
  Mat3 linear() const;
  /// μ' = μ + t.
  Vec3 apply_to_mean(const Vec3& mean) const { return mean + translation; }
  /// Σ' = A Σ Aᵀ, symmetrised.
  Mat3 apply_to_covariance(const Mat3& covariance) const;
  /// The change with weight w ∈ [0, 1]: w·t, the rotation by w of its angle, the scale s^w.
  GaussianChange weighted(double w) const;
  /// The change seen in the mirror across the plane x_axis = 0: M t, M R M, M u (M the reflection).
  GaussianChange mirrored(int axis) const;
};

}  // namespace gps
