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
      compact_("compact", {{GL_COMPUTE_SHADER, {shaders::gpu_layout, shaders::compact_comp}}}) {
  glCreateBuffers(1, &table_);
  glCreateBuffers(1, &block_starts_);
}

StoredVertexWeld::~StoredVertexWeld() {
  glDeleteBuffers(1, &table_);
  glDeleteBuffers(1, &block_starts_);
}

void StoredVertexWeld::weld(unsigned vertices, unsigned indices, unsigned welded_vertices, const std::vector<Range>& ranges,
                            const std::vector<long long>& block_starts) {
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
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingStoredVertices, vertices);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingWeldTable, table_);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingStoredIndices, indices);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingBlockStarts, block_starts_);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingWeldedVertices, welded_vertices);
  for (const ShaderProgram* p : {&weld_, &compact_}) {
    p->use();
    p->set("u_blocks", int(starts.size()));
  }
  const GLuint zero = 0;
  for (const Range& r : ranges) {
    if (r.count <= 0) continue;
    glClearNamedBufferSubData(table_, GL_R32UI, 0, GLsizeiptr(2 * r.count * 4), GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
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
  glMemoryBarrier(GL_ELEMENT_ARRAY_BARRIER_BIT | GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT);
  check_gl_errors("welding the surface cache");
}

}  // namespace gps
