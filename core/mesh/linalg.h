#pragma once
// Small dense types used throughout core (Eigen, double precision).
#include <Eigen/Core>

namespace gps {
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
/// A Gaussian's dual vector q = (vech(Σ⁻¹), Σ⁻¹μ): xx xy xz yy yz zz, then 3 (thesis Eq. 2.10).
using Dual = Eigen::Matrix<double, 9, 1>;
}  // namespace gps
