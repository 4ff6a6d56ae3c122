// The work groups of one dispatch that evaluates the welded vertices of several blocks again
// (render/cache/stored_vertex_evaluation.h): one invocation sums the listed blocks' work groups (written
// by their weld, shaders/compact_comp.glsl) into each block's first group and the indirect
// dispatch's count, so that an edit of many blocks is one dispatch (each dispatch has its own cost).
layout(local_size_x = 1) in;
layout(std430, binding = kBindingWeldedDispatches) readonly buffer WeldedDispatches { uint dispatches[]; };  // 3 words a block
layout(std430, binding = kBindingEvaluationBlocks) readonly buffer EvaluationBlocks { int blocks[]; };  // block, first vertex, bound
layout(std430, binding = kBindingEvaluationGroups) writeonly buffer EvaluationGroups { uint groups[]; };  // dispatch, then first groups
uniform int u_blocks;

void main() {
  uint total = 0u;
  for (int j = 0; j < u_blocks; ++j) {
    groups[3 + j] = total;
    total += dispatches[3 * blocks[3 * j]];
  }
  groups[0] = total;
  groups[1] = 1u;
  groups[2] = 1u;
}
