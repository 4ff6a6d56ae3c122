#include "render/cache/stored_vertex_weld.h"

#include <glad/gl.h>

#include <algorithm>

#include "render/gl/compute_limits.h"
#include "shaders/embedded_shaders.h"
#include "render/gl/gl_context.h"
#include "render/gl/gpu_layout.h"

namespace gps {

StoredVertexWeld::StoredVertexWeld()
    : weld_("weld", {{GL_COMPUTE_SHADER, {shaders::gpu_layout, shaders::weld_comp}}}),
      compact_("compact", {{GL_COMPUTE_SHADER, {shaders::gpu_layout, shaders::compact_comp}}}),
      copy_back_("unweld", {{GL_COMPUTE_SHADER, {shaders::gpu_layout, shaders::unweld_comp}}}),
      reweld_("reweld", {{GL_COMPUTE_SHADER, {shaders::gpu_layout, shaders::reweld_comp}}}) {}

void StoredVertexWeld::weld(unsigned vertices, unsigned indices, unsigned welded_vertices, unsigned parameters,
                            long long count, const std::vector<long long>& block_starts) {
  if (count <= 0) return;
  if (2 * count > slots_ || 8 * count < slots_) {  // the table: twice the vertices
    slots_ = 2 * count;
    glNamedBufferData(table_, GLsizeiptr(slots_ * 4), nullptr, GL_DYNAMIC_COPY);
  }
  // The blocks' first vertices, then per chunk of kBlockChunk vertices, and one past them, the block of
  // its first (shaders/stored_blocks.glsl).
  const long long blocks = (long long)block_starts.size();
  std::vector<GLuint> starts;
  starts.reserve(size_t(blocks + count / gpu::kBlockChunk + 2));
  starts.assign(block_starts.begin(), block_starts.end());
  GLuint block = 0;
  for (long long first = 0; first < count + gpu::kBlockChunk; first += gpu::kBlockChunk) {
    while (block + 1 < GLuint(blocks) && block_starts[block + 1] <= first) ++block;
    starts.push_back(block);
  }
  glNamedBufferData(block_starts_, GLsizeiptr(starts.size() * sizeof(GLuint)), starts.data(), GL_STREAM_DRAW);
  if (blocks > counted_blocks_) {
    counted_blocks_ = blocks;
    glNamedBufferData(welded_counts_, GLsizeiptr(blocks * 4), nullptr, GL_DYNAMIC_COPY);
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingStoredVertices, vertices);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingWeldTable, table_);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingStoredIndices, indices);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingBlockStarts, block_starts_);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingWeldedVertices, welded_vertices);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingWeldedParameters, parameters);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingWeldedCounts, welded_counts_);
  const GLuint zero = 0;
  glClearNamedBufferSubData(table_, GL_R32UI, 0, GLsizeiptr(2 * count * 4), GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  // No welded vertices in a block until its last vertex counts them (none in an empty block).
  glClearNamedBufferSubData(welded_counts_, GL_R32UI, 0, GLsizeiptr(blocks * 4), GL_RED_INTEGER, GL_UNSIGNED_INT,
                            &zero);
  scan_.bind(count);
  weld_.use();
  weld_.set("u_slots", int(2 * count));
  run_compute_pass(weld_, int(count), false, 0);
  scan_.run(count);
  compact_.use();
  compact_.set("u_blocks", int(blocks));
  run_compute_pass(compact_, int(count), false, 0);
  glMemoryBarrier(GL_ELEMENT_ARRAY_BARRIER_BIT | GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  check_gl_errors("welding the surface cache");
}

long long StoredVertexWeld::upload_runs(const std::vector<Range>& ranges) {
  std::vector<GLuint> runs;
  long long total = 0;
  for (const Range& r : ranges) {
    if (r.count <= 0) continue;
    if (!runs.empty() &&
        runs[runs.size() - 2] + (total - runs.back()) == GLuint(r.first)) {  // goes on from the last run
      total += r.count;
      continue;
    }
    runs.insert(runs.end(), {GLuint(r.first), GLuint(total)});
    total += r.count;
  }
  if (total == 0) return 0;
  glNamedBufferData(runs_, GLsizeiptr(runs.size() * sizeof(GLuint)), runs.data(), GL_STREAM_DRAW);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingCopyRuns, runs_);
  for (const ShaderProgram* p : {&copy_back_, &reweld_}) {
    p->use();
    p->set("u_runs", int(runs.size() / 2));
  }
  return total;
}

void StoredVertexWeld::weld_again(unsigned vertices, unsigned indices, unsigned welded_vertices, unsigned parameters,
                                  const std::vector<Range>& ranges) {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingStoredVertices, vertices);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingStoredIndices, indices);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingWeldedVertices, welded_vertices);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingWeldedParameters, parameters);
  const long long total = upload_runs(ranges);
  if (total == 0) return;
  run_compute_pass(reweld_, int(total), false, 0);
  glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  check_gl_errors("welding blocks again");
}

void StoredVertexWeld::copy_back(unsigned vertices, unsigned indices, unsigned welded_vertices,
                                 const std::vector<Range>& ranges) {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingStoredVertices, vertices);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingStoredIndices, indices);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingWeldedVertices, welded_vertices);
  const long long total = upload_runs(ranges);
  if (total == 0) return;
  run_compute_pass(copy_back_, int(total), false, 0);
  glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT |
                  GL_TRANSFORM_FEEDBACK_BARRIER_BIT);
  check_gl_errors("copying welded vertices back");
}

}  // namespace gps
