#include "render/cache/stored_vertex_evaluation.h"

#include <glad/gl.h>

#include <algorithm>

#include "render/gl/gl_context.h"
#include "render/gl/gpu_layout.h"
#include "shaders/embedded_shaders.h"

namespace gps {

StoredVertexEvaluation::StoredVertexEvaluation()
    : programs_(plan_compute_programs("stored_vertex_evaluation", true, {shaders::stored_vertex_evaluation_comp})),
      leaf_programs_(plan_compute_programs("stored_vertex_evaluation_leaves", true,
                                           {shaders::stored_vertex_evaluation_comp}, "#define GPS_LEAVES_ONLY\n")),
      groups_program_("evaluation_groups",
                      {{GL_COMPUTE_SHADER, {shaders::gpu_layout, shaders::evaluation_groups_comp}}}) {}

void StoredVertexEvaluation::set_precision(PointPrecision precision) {
  programs_.set_precision(precision);
  leaf_programs_.set_precision(precision, false);  // the same program less a branch: checked above
}

void StoredVertexEvaluation::run(const PatchPlans& plans, const std::vector<Block>& blocks, unsigned welded_counts,
                                 int group_limit) {
  std::vector<Block> leaves, exact;
  for (const Block& b : blocks) {
    bool holds = false;
    for (int p = b.first_patch; p < b.first_patch + b.patches && !holds; ++p)
      holds = holds_extraordinary_node(plans, plans.patch_roots[size_t(p)]);
    (holds ? exact : leaves).push_back(b);
  }
  run_with(leaf_programs_, plans.shape, leaves, welded_counts, group_limit);
  run_with(programs_, plans.shape, exact, welded_counts, group_limit);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT);
  check_gl_errors("evaluating the stored vertices");
}

void StoredVertexEvaluation::run_with(const ShapePrograms& programs, PatchShape shape, const std::vector<Block>& blocks,
                                      unsigned welded_counts, int group_limit) {
  if (blocks.empty()) return;
  GLint max_groups = 0;
  glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &max_groups);
  if (group_limit > 0) max_groups = std::min(max_groups, group_limit);
  // The blocks in runs that fit a dispatch: a block's welded vertices are fewer than its bound, so
  // many work groups at most.
  for (size_t begin = 0; begin < blocks.size();) {
    size_t end = begin;
    long long groups = 0;
    while (end < blocks.size()) {
      const long long most = (blocks[end].bound + gpu::kWorkGroupSize - 1) / gpu::kWorkGroupSize;
      if (end > begin && groups + most > max_groups) break;
      groups += most;
      ++end;
    }
    dispatch(programs(shape), std::vector<Block>(blocks.begin() + long(begin), blocks.begin() + long(end)),
             welded_counts);
    begin = end;
  }
}

void StoredVertexEvaluation::dispatch(const ShaderProgram& program, const std::vector<Block>& blocks,
                                      unsigned welded_counts) {
  std::vector<GLint> listed;
  listed.reserve(3 * blocks.size());
  for (const Block& b : blocks) listed.insert(listed.end(), {GLint(b.block), GLint(b.first), GLint(b.bound)});
  glNamedBufferData(blocks_, GLsizeiptr(listed.size() * sizeof(GLint)), listed.data(), GL_STREAM_DRAW);
  glNamedBufferData(groups_, GLsizeiptr((4 + blocks.size()) * sizeof(GLuint)), nullptr, GL_STREAM_COPY);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingWeldedCounts, welded_counts);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingEvaluationBlocks, blocks_);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingEvaluationGroups, groups_);
  groups_program_.use();
  groups_program_.set("u_blocks", int(blocks.size()));
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  program.use();
  program.set("u_blocks", int(blocks.size()));
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, groups_);
  glDispatchComputeIndirect(0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);  // the list and groups buffers' reuse
}

}  // namespace gps
