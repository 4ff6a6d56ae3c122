// Numbers a welded range's distinct vertices block by block (render/stored_vertex_weld.h): a
// vertex that is its own index is copied to its block's first vertex plus the number of distinct
// vertices before it in the block (from the exclusive prefix sum of shaders/weld_comp.glsl's
// flags), and every vertex's index becomes its representative's number. The welded vertices of a
// block thus lie together, in the order they were captured, as a welded static buffer's do: a
// vertex cache keyed by index (llvmpipe's) finds the shared ones.
#include "shaders/compute_pass.glsl"
#include "shaders/stored_blocks.glsl"
layout(std430, binding = kBindingStoredVertices) readonly buffer StoredVertices { uint stored[]; };  // 9 words a vertex
layout(std430, binding = kBindingStoredIndices) buffer StoredIndices { uint indices[]; };
layout(std430, binding = kBindingScanValues) readonly buffer DistinctBefore { uint distinct_before[]; };  // per range vertex
layout(std430, binding = kBindingWeldedVertices) writeonly buffer WeldedVertices { uint welded[]; };
uniform int u_range_first;  // the range's first vertex (a block's); invocation i numbers vertex u_range_first + i

void main() {
  int i = compute_invocation();
  if (i < 0) return;
  uint first = uint(u_range_first), v = first + uint(i), representative = indices[v];
  uint start = block_starts[block_of(v)];
  uint number = start + distinct_before[representative - first] - distinct_before[start - first];
  indices[v] = number;
  if (representative == v)
    for (uint k = 0u; k < 9u; ++k) welded[9u * number + k] = stored[9u * v + k];
}
