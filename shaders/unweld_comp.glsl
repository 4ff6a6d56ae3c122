// Copies the welded vertices' position and stored normal back to the captured vertices they stand
// for (render/stored_vertex_weld.h), after they were evaluated again (an edit): the captured
// buffer stays what a capture would hold, for the frames and refreshes that read it. One pass over
// runs of captured vertices: invocation i copies to the vertex i − (the run's invocations before)
// past its run's first.
#include "shaders/compute_pass.glsl"
layout(std430, binding = kBindingStoredVertices) buffer StoredVertices { uint stored[]; };  // 12 words a vertex
layout(std430, binding = kBindingStoredIndices) readonly buffer StoredIndices { uint indices[]; };
layout(std430, binding = kBindingWeldedVertices) readonly buffer WeldedVertices { uint welded[]; };  // 9 words a vertex
layout(std430, binding = kBindingCopyRuns) readonly buffer CopyRuns { uint runs[]; };  // per run: first vertex, invocations before
uniform int u_runs;

void main() {
  int i = compute_invocation();
  if (i < 0) return;
  int low = 0, high = u_runs - 1;  // the last run whose invocations start at or before i
  while (low < high) {
    int middle = (low + high + 1) / 2;
    if (runs[2 * middle + 1] <= uint(i)) low = middle;
    else high = middle - 1;
  }
  uint v = runs[2 * low] + uint(i) - runs[2 * low + 1], w = indices[v];
  for (uint k = 0u; k < 6u; ++k) stored[12u * v + k] = welded[9u * w + k];
}
