#pragma once
// Editing a Gaussian through its ellipsoid: principal axes, scaling one axis, rotating the frame,
// and keeping the result symmetric positive definite whatever the user drags in the editor.
#include "core/mesh/linalg.h"

namespace gps {

/// The principal axes of a covariance: unit axes as columns (right-handed) and standard deviations.
struct EllipsoidAxes {
  Mat3 axes;
  Vec3 sigmas;
};

/// Σ = V diag(σ²) Vᵀ, eigenvalues ascending.
EllipsoidAxes ellipsoid_axes(const Mat3& covariance);

/// The covariance with these axes and standard deviations.
Mat3 covariance_from_axes(const Mat3& axes, const Vec3& sigmas);

/// Symmetric, with eigenvalues clamped to [min_variance, max_variance]; never NaN (a non-finite
/// input gives `fallback`).
Mat3 clamp_spd(const Mat3& covariance, const Mat3& fallback, double min_variance = 1e-10, double max_variance = 1e10);

/// Multiplies the standard deviation along principal axis `axis` (0..2, ascending) by `factor` (> 0).
Mat3 scale_axis(const Mat3& covariance, int axis, double factor);

/// R Σ Rᵀ: the same ellipsoid turned by the rotation R (eigenvalues kept).
Mat3 rotate_covariance(const Mat3& covariance, const Mat3& rotation);

/// Dragging the end of an axis handle that sits r from the centre by d along the axis scales that
/// standard deviation by (r + d)/r, kept above a small positive floor.
double axis_drag_factor(double handle_distance, double drag_along_axis);

}  // namespace gps
