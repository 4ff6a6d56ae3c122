// Maps base Gaussians (μ, Σ⁻¹) to their 9D points q = (vech(Σ⁻¹), Σ⁻¹μ) (thesis Eq. 2.10), kept about
// μ itself: y = 0, anchor μ (plan_point.glsl). Σ⁻¹ comes inverted in double (plan_buffers.cpp).
#include "shaders/compute_pass.glsl"
layout(std430, binding = kBindingGaussians) readonly buffer Gaussians { float gaussians[]; };  // 9 per vertex: μ, Σ⁻¹ xx xy xz yy yz zz
layout(std430, binding = kBindingPoints) buffer Points { vec4 points[]; };
layout(std430, binding = kBindingChanged) readonly buffer Changed { int changed[]; };

void main() {
  int i = compute_invocation();
  if (i < 0) return;
  int v = u_use_list != 0 ? changed[i] : i;
  float g[9];
  for (int k = 0; k < 9; ++k) g[k] = gaussians[9 * v + k];
  mat3 p = mat3(g[3], g[4], g[5], g[4], g[6], g[7], g[5], g[7], g[8]);
  vec3 mu = vec3(g[0], g[1], g[2]);
  points[kVec4PerPoint * v] = vec4(p[0][0], p[0][1], p[0][2], p[1][1]);
  points[kVec4PerPoint * v + 1] = vec4(p[1][2], p[2][2], 0.0, 0.0);
  points[kVec4PerPoint * v + 2] = vec4(0.0, mu);
}
