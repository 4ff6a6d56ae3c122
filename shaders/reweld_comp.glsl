// The welded vertices of blocks captured again in the tessellation they had (render/cache/stored_vertex_weld.h):
// the same vertices in the same slots, so each keeps the welded vertex it stood for, and writes its
// words there (position and normal, and apart the patch and parameters it was evaluated at), which
// copies of one point have alike. One pass over runs of captured vertices.
#include "shaders/compute_pass.glsl"
#include "shaders/copy_runs.glsl"
layout(std430, binding = kBindingStoredVertices) readonly buffer StoredVertices { uint stored[]; };  // 12 words a vertex
layout(std430, binding = kBindingStoredIndices) readonly buffer StoredIndices { uint indices[]; };
layout(std430, binding = kBindingWeldedVertices) writeonly buffer WeldedVertices { uint welded[]; };       // 6 words a vertex
layout(std430, binding = kBindingWeldedParameters) writeonly buffer WeldedParameters { uint parameters[]; };  // 3 words a vertex

void main() {
  int i = compute_invocation();
  if (i < 0) return;
  uint v = run_vertex(i), w = indices[v];
  for (uint k = 0u; k < 6u; ++k) welded[6u * w + k] = stored[12u * v + k];
  for (uint k = 0u; k < 3u; ++k) parameters[3u * w + k] = stored[12u * v + 9u + k];
}
