// Cubic bases of the plan nodes; mirrors core/patch_basis.h line for line.
void bspline_basis(float t, out float w[4], out float dw[4]) {
  float s = 1.0 - t, t2 = t * t;
  w[0] = s * s * s / 6.0;
  w[1] = (3.0 * t2 * t - 6.0 * t2 + 4.0) / 6.0;
  w[2] = (-3.0 * t2 * t + 3.0 * t2 + 3.0 * t + 1.0) / 6.0;
  w[3] = t2 * t / 6.0;
  dw[0] = -0.5 * s * s;
  dw[1] = 1.5 * t2 - 2.0 * t;
  dw[2] = -1.5 * t2 + t + 0.5;
  dw[3] = 0.5 * t2;
}

void bezier_basis(float t, out float w[4], out float dw[4]) {
  float s = 1.0 - t;
  w[0] = s * s * s;
  w[1] = 3.0 * t * s * s;
  w[2] = 3.0 * t * t * s;
  w[3] = t * t * t;
  dw[0] = -3.0 * s * s;
  dw[1] = 3.0 * s * s - 6.0 * t * s;
  dw[2] = 6.0 * t * s - 3.0 * t * t;
  dw[3] = 3.0 * t * t;
}
