// The corner pass's zeroes (render/pipeline/corner_limit_pass.h): the items of its list from u_from on,
// each a slot that holds no corner limit or no curve midpoint, zeroed as the buffers are after
// allocation. A pass of their own: a software driver runs a batch of them through the evaluation
// program's whole body, its lanes masked off, at a good part of an evaluation's cost.
#include "shaders/compute_pass.glsl"
layout(std430, binding = kBindingCornerLimits) writeonly buffer CornerLimits { vec4 corner_limits[]; };
layout(std430, binding = kBindingCurveMidpoints) writeonly buffer CurveMidpoints { vec4 curve_midpoints[]; };
layout(std430, binding = kBindingCornerList) readonly buffer CornerList { int corner_items[]; };  // gpu_layout.h: kCornerItemOps
uniform int u_from;  // the list's first zero

void main() {
  int i = compute_invocation();
  if (i < 0) return;
  int item = corner_items[u_from + i];
  int slot = item / kCornerItemOps;
  if (item - kCornerItemOps * slot == kCornerItemClearMidpoint) {
    curve_midpoints[slot] = vec4(0.0);
  } else {
    corner_limits[2 * slot] = vec4(0.0);
    corner_limits[2 * slot + 1] = vec4(0.0);
  }
}
