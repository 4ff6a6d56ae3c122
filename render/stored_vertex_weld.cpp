#include "render/stored_vertex_weld.h"

#include <glad/gl.h>

#include <algorithm>

#include "render/compute_limits.h"
#include "shaders/embedded_shaders.h"
#include "render/gl_context.h"
#include "render/gpu_layout.h"

namespace gps {

StoredVertexWeld::StoredVertexWeld()
    : weld_("weld", {{GL_COMPUTE_SHADER, {shaders::gpu_layout, shaders::weld_comp}}}),
      compact_("compact", {{GL_COMPUTE_SHADER, {shaders::gpu_layout, shaders::compact_comp}}}),
      copy_back_("unweld", {{GL_COMPUTE_SHADER, {shaders::gpu_layout, shaders::unweld_comp}}}) {
  glCreateBuffers(1, &table_);
  glCreateBuffers(1, &block_starts_);
  glCreateBuffers(1, &dispatches_);
  glCreateBuffers(1, &runs_);
}

StoredVertexWeld::~StoredVertexWeld() {
  glDeleteBuffers(1, &table_);
  glDeleteBuffers(1, &block_starts_);
  glDeleteBuffers(1, &dispatches_);
  glDeleteBuffers(1, &runs_);
}

void StoredVertexWeld::weld(unsigned vertices, unsigned indices, unsigned welded_vertices, unsigned parameters,
                            const std::vector<Range>& ranges, const std::vector<long long>& block_starts) {
  long long most = 0;
  for (const Range& r : ranges) most = std::max(most, r.count);
  if (most <= 0) return;
  // One table for the largest range, cleared before each; the block starts uploaded once.
  if (2 * most > slots_ || 8 * most < slots_) {
    slots_ = 2 * most;
    glNamedBufferData(table_, GLsizeiptr(slots_ * 4), nullptr, GL_DYNAMIC_COPY);
  }
  std::vector<GLuint> starts(block_starts.begin(), block_starts.end());
  glNamedBufferData(block_starts_, GLsizeiptr(starts.size() * sizeof(GLuint)), starts.data(), GL_STREAM_DRAW);
  const long long blocks = (long long)starts.size();
  if (blocks > dispatch_blocks_) {  // more blocks: a new capture, welded whole
    dispatch_blocks_ = blocks;
    glNamedBufferData(dispatches_, GLsizeiptr(3 * blocks * 4), nullptr, GL_DYNAMIC_COPY);
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingStoredVertices, vertices);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingWeldTable, table_);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingStoredIndices, indices);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingBlockStarts, block_starts_);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingWeldedVertices, welded_vertices);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingWeldedParameters, parameters);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingWeldedDispatches, dispatches_);
  for (const ShaderProgram* p : {&weld_, &compact_}) {
    p->use();
    p->set("u_blocks", int(starts.size()));
  }
  const GLuint zero = 0, none = ~0u;
  for (const Range& r : ranges) {
    if (r.count <= 0) continue;
    glClearNamedBufferSubData(table_, GL_R32UI, 0, GLsizeiptr(2 * r.count * 4), GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    glClearNamedBufferSubData(parameters, GL_R32UI, GLintptr(3 * r.first * 4), GLsizeiptr(3 * r.count * 4), GL_RED_INTEGER,
                              GL_UNSIGNED_INT, &none);
    // The range's blocks: no work groups until their last vertex writes them (none for an empty block).
    const auto first_block = std::lower_bound(starts.begin(), starts.end(), GLuint(r.first)) - starts.begin();
    const auto end_block = std::lower_bound(starts.begin(), starts.end(), GLuint(r.first + r.count)) - starts.begin();
    glClearNamedBufferSubData(dispatches_, GL_R32UI, GLintptr(3 * first_block * 4), GLsizeiptr(3 * (end_block - first_block) * 4),
                              GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    scan_.bind(r.count);
    weld_.use();
    weld_.set("u_range_first", int(r.first));
    weld_.set("u_slots", int(2 * r.count));
    run_compute_pass(weld_, int(r.count), false, 0);  // its barrier orders the table's reuse
    scan_.run(r.count);
    compact_.use();
    compact_.set("u_range_first", int(r.first));
    run_compute_pass(compact_, int(r.count), false, 0);
  }
  glMemoryBarrier(GL_ELEMENT_ARRAY_BARRIER_BIT | GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  check_gl_errors("welding the surface cache");
}

void StoredVertexWeld::copy_back(unsigned vertices, unsigned indices, unsigned welded_vertices, const std::vector<Range>& ranges) {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingStoredVertices, vertices);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingStoredIndices, indices);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingWeldedVertices, welded_vertices);
  std::vector<GLuint> runs;
  long long total = 0;
  for (const Range& r : ranges) {
    if (r.count <= 0) continue;
    if (!runs.empty() && runs[runs.size() - 2] + (total - runs.back()) == GLuint(r.first)) {  // goes on from the last run
      total += r.count;
      continue;
    }
    runs.insert(runs.end(), {GLuint(r.first), GLuint(total)});
    total += r.count;
  }
  if (total == 0) return;
  glNamedBufferData(runs_, GLsizeiptr(runs.size() * sizeof(GLuint)), runs.data(), GL_STREAM_DRAW);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingCopyRuns, runs_);
  copy_back_.use();
  copy_back_.set("u_runs", int(runs.size() / 2));
  run_compute_pass(copy_back_, int(total), false, 0);
  glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT | GL_TRANSFORM_FEEDBACK_BARRIER_BIT);
  check_gl_errors("copying welded vertices back");
}

}  // namespace gps
