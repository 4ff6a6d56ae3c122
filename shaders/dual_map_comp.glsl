// Maps base Gaussians (μ, Σ⁻¹) to their 9D points q = (vech(Σ⁻¹), Σ⁻¹μ) (thesis Eq. 2.10), kept about
// μ itself: anchor μ (plan_point.glsl). Σ⁻¹ comes inverted in double (plan_buffers.cpp); float points
// take y = 0, double ones (GPS_DOUBLE) core's own q̄ as y = q̄ − Σ⁻¹ μ.
#include "shaders/compute_pass.glsl"
layout(std430, binding = kBindingGaussians) readonly buffer Gaussians { point_real gaussians[]; };  // μ, Σ⁻¹ xx xy xz yy yz zz (double: y)
layout(std430, binding = kBindingPoints) buffer Points { point_vec4 points[]; };
layout(std430, binding = kBindingChanged) readonly buffer Changed { int changed[]; };

void main() {
  int i = compute_invocation();
  if (i < 0) return;
  int v = u_use_list != 0 ? changed[i] : i;
#ifdef GPS_DOUBLE
  const int kGaussianReals = 12;
  point_real g[12];
#else
  const int kGaussianReals = 9;
  point_real g[9];
#endif
  for (int k = 0; k < kGaussianReals; ++k) g[k] = gaussians[kGaussianReals * v + k];
  point_mat3 p = point_mat3(g[3], g[4], g[5], g[4], g[6], g[7], g[5], g[7], g[8]);
  point_vec3 mu = point_vec3(g[0], g[1], g[2]);
  points[kVec4PerPoint * v] = point_vec4(p[0][0], p[0][1], p[0][2], p[1][1]);
#ifdef GPS_DOUBLE
  points[kVec4PerPoint * v + 1] = point_vec4(p[1][2], p[2][2], g[9], g[10]);
  points[kVec4PerPoint * v + 2] = point_vec4(g[11], mu);
#else
  points[kVec4PerPoint * v + 1] = point_vec4(p[1][2], p[2][2], 0.0, 0.0);
  points[kVec4PerPoint * v + 2] = point_vec4(0.0, mu);
#endif
}
