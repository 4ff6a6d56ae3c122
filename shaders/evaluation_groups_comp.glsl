// The invocations of one dispatch that evaluates the welded vertices of several blocks again
// (render/cache/stored_vertex_evaluation.h): one invocation sums the listed blocks' welded vertices
// (written by their weld, shaders/compact_comp.glsl) into each block's first invocation, the total
// after the last, and the indirect dispatch's work groups, so that an edit of many blocks is one
// dispatch (each dispatch has its own cost) whose work groups are filled across blocks (a block's
// own groups would each end part empty, which small blocks make most of the work).
layout(local_size_x = 1) in;
layout(std430, binding = kBindingWeldedCounts) readonly buffer WeldedCounts { uint welded_counts[]; };  // per block
layout(std430, binding = kBindingEvaluationBlocks) readonly buffer EvaluationBlocks { int blocks[]; };  // block, first vertex, bound
layout(std430, binding = kBindingEvaluationGroups) writeonly buffer EvaluationGroups { uint groups[]; };  // dispatch, then first invocations
uniform int u_blocks;

void main() {
  uint total = 0u;
  for (int j = 0; j < u_blocks; ++j) {
    groups[3 + j] = total;
    total += min(welded_counts[blocks[3 * j]], uint(blocks[3 * j + 2]));
  }
  groups[3 + u_blocks] = total;
  groups[0] = (total + uint(kWorkGroupSize) - 1u) / uint(kWorkGroupSize);
  groups[1] = 1u;
  groups[2] = 1u;
}
