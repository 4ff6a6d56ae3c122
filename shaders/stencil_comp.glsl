// Applies the stencil table: point first_row + r = Σ w · q[index] (one sparse matrix-vector product), the
// sum taken about an anchor, the row's heaviest point's, which the row keeps (plan_point.glsl).
#include "shaders/compute_pass.glsl"
layout(std430, binding = kBindingPoints) buffer Points { point_vec4 points[]; };  // gpu_layout.h
#include "shaders/plan_point.glsl"
layout(std430, binding = kBindingOffsets) readonly buffer Offsets { int offsets[]; };
layout(std430, binding = kBindingIndices) readonly buffer Indices { int indices[]; };
layout(std430, binding = kBindingWeights) readonly buffer Weights { float weights[]; };
layout(std430, binding = kBindingRows) readonly buffer Rows { int rows[]; };
uniform int u_first_row;  // core/plans/patch_plans.h: StencilTable::first_row()

void main() {
  int i = compute_invocation();
  if (i < 0) return;
  int r = u_use_list != 0 ? rows[i] : i;
  int begin = offsets[r], end = offsets[r + 1];
  // The anchor: that of the point weighing most (|w| tr q̂), which keeps the largest term small.
  int heaviest = begin;
  float most = 0.0;
  for (int k = begin; k < end; ++k) {
    float weight = abs(weights[k]) * abs(point_precision_trace(indices[k]));
    heaviest = weight > most ? k : heaviest;
    most = max(most, weight);
  }
  point_vec3 anchor = point_anchor(indices[heaviest]);
  point_vec4 a = point_vec4(0.0), b = point_vec4(0.0), c = point_vec4(0.0);
  for (int k = begin; k < end; ++k) {
    point_vec4 pa, pb, pc;
    anchored_point(indices[k], anchor, pa, pb, pc);
    float w = weights[k];
    a += w * pa;
    b += w * pb;
    c += w * pc;
  }
  c.yzw = anchor;
  int out_point = u_first_row + r;
  points[kVec4PerPoint * out_point] = a;
  points[kVec4PerPoint * out_point + 1] = b;
  points[kVec4PerPoint * out_point + 2] = c;
}
