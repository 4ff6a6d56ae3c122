// Applies the stencil table: point n_base + r = Σ w · q[index] (one sparse matrix-vector product).
#include "shaders/compute_pass.glsl"
layout(std430, binding = kBindingPoints) buffer Points { vec4 points[]; };
layout(std430, binding = kBindingOffsets) readonly buffer Offsets { int offsets[]; };
layout(std430, binding = kBindingIndices) readonly buffer Indices { int indices[]; };
layout(std430, binding = kBindingWeights) readonly buffer Weights { float weights[]; };
layout(std430, binding = kBindingRows) readonly buffer Rows { int rows[]; };
uniform int u_n_base;

void main() {
  int i = compute_invocation();
  if (i < 0) return;
  int r = u_use_list != 0 ? rows[i] : i;
  vec4 a = vec4(0.0), b = vec4(0.0), c = vec4(0.0);
  for (int k = offsets[r]; k < offsets[r + 1]; ++k) {
    int p = indices[k];
    float w = weights[k];
    a += w * points[kVec4PerPoint * p];
    b += w * points[kVec4PerPoint * p + 1];
    c += w * points[kVec4PerPoint * p + 2];
  }
  int out_point = u_n_base + r;
  points[kVec4PerPoint * out_point] = a;
  points[kVec4PerPoint * out_point + 1] = b;
  points[kVec4PerPoint * out_point + 2] = c;
}
