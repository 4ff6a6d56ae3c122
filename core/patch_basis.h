#pragma once
// The cubic bases of the patches in a plan (thesis 2.3); shaders/patch_basis.glsl mirrors this file.

namespace gps {

/// Uniform cubic B-spline basis on one segment, t in [0,1]: values w[0..3] and derivatives dw[0..3].
inline void bspline_basis(double t, double w[4], double dw[4]) {
  const double s = 1.0 - t, t2 = t * t;
  w[0] = s * s * s / 6.0;
  w[1] = (3.0 * t2 * t - 6.0 * t2 + 4.0) / 6.0;
  w[2] = (-3.0 * t2 * t + 3.0 * t2 + 3.0 * t + 1.0) / 6.0;
  w[3] = t2 * t / 6.0;
  dw[0] = -0.5 * s * s;
  dw[1] = 1.5 * t2 - 2.0 * t;
  dw[2] = -1.5 * t2 + t + 0.5;
  dw[3] = 0.5 * t2;
}

/// Cubic Bernstein basis, t in [0,1]: values w[0..3] and derivatives dw[0..3].
inline void bezier_basis(double t, double w[4], double dw[4]) {
  const double s = 1.0 - t;
  w[0] = s * s * s;
  w[1] = 3.0 * t * s * s;
  w[2] = 3.0 * t * t * s;
  w[3] = t * t * t;
  dw[0] = -3.0 * s * s;
  dw[1] = 3.0 * s * s - 6.0 * t * s;
  dw[2] = 6.0 * t * s - 3.0 * t * t;
  dw[3] = 3.0 * t * t;
}

}  // namespace gps
