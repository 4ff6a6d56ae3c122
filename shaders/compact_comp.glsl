// Numbers the welded distinct vertices block by block (render/cache/stored_vertex_weld.h): a vertex that
// is its own index is copied (its position and normal, and apart the patch and parameters it was
// evaluated at) to its block's first vertex plus the number of distinct vertices before it in the block
// (from the exclusive prefix sum of shaders/weld_comp.glsl's flags), and every vertex's index
// becomes its representative's number (the representative may lie in another block). The welded
// vertices of a block thus lie together, in the order they were captured, as a welded static
// buffer's do: a vertex cache keyed by index (llvmpipe's) finds the shared ones.
#include "shaders/compute_pass.glsl"
#include "shaders/stored_blocks.glsl"
layout(std430, binding = kBindingStoredVertices) readonly buffer StoredVertices { uint stored[]; };  // 12 words a vertex
layout(std430, binding = kBindingStoredIndices) buffer StoredIndices { uint indices[]; };
layout(std430, binding = kBindingScanValues) readonly buffer DistinctBefore { uint distinct_before[]; };  // per vertex
layout(std430, binding = kBindingWeldedVertices) writeonly buffer WeldedVertices { uint welded[]; };       // 6 words a vertex
layout(std430, binding = kBindingWeldedParameters) writeonly buffer WeldedParameters { uint parameters[]; };  // 3 words a vertex
layout(std430, binding = kBindingWeldedCounts) writeonly buffer WeldedCounts { uint welded_counts[]; };  // per block

void main() {
  int i = compute_invocation();
  if (i < 0) return;
  uint v = uint(i), representative = indices[v];
  int block = block_of(v);
  uint start = block_starts[block], representative_start = block_starts[block_of(representative)];
  uint number = representative_start + distinct_before[representative] - distinct_before[representative_start];
  indices[v] = number;
  if (representative == v) {
    for (uint k = 0u; k < 6u; ++k) welded[6u * number + k] = stored[12u * v + k];
    for (uint k = 0u; k < 3u; ++k) parameters[3u * number + k] = stored[12u * v + 9u + k];
  }
  // The block's last vertex: how many welded vertices the block has, which an evaluation of them
  // again runs over (render/cache/stored_vertex_evaluation.h).
  uint end = block + 1 < u_blocks ? block_starts[block + 1] : uint(u_count);
  if (v + 1u == end) {
    welded_counts[block] = distinct_before[v] + (representative == v ? 1u : 0u) - distinct_before[start];
  }
}
