// Copies the welded vertices' position and stored normal back to the captured vertices they stand
// for (render/cache/stored_vertex_weld.h), after they were evaluated again (an edit): the captured
// buffer stays what a capture would hold, for the frames and refreshes that read it. One pass over
// runs of captured vertices.
#include "shaders/compute_pass.glsl"
#include "shaders/copy_runs.glsl"
layout(std430, binding = kBindingStoredVertices) buffer StoredVertices { uint stored[]; };  // 12 words a vertex
layout(std430, binding = kBindingStoredIndices) readonly buffer StoredIndices { uint indices[]; };
layout(std430, binding = kBindingWeldedVertices) readonly buffer WeldedVertices { uint welded[]; };  // 6 words a vertex

void main() {
  int i = compute_invocation();
  if (i < 0) return;
  uint v = run_vertex(i), w = indices[v];
  for (uint k = 0u; k < 6u; ++k) stored[12u * v + k] = welded[6u * w + k];
}
