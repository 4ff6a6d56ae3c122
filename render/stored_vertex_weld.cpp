#include "render/stored_vertex_weld.h"

#include <glad/gl.h>

#include <algorithm>

#include "render/compute_limits.h"
#include "shaders/embedded_shaders.h"
#include "render/gl_context.h"
#include "render/gpu_layout.h"

namespace gps {

StoredVertexWeld::StoredVertexWeld() : program_("weld", {{GL_COMPUTE_SHADER, {shaders::gpu_layout, shaders::weld_comp}}}) {
  glCreateBuffers(1, &table_);
  glCreateBuffers(1, &block_starts_);
}

StoredVertexWeld::~StoredVertexWeld() {
  glDeleteBuffers(1, &table_);
  glDeleteBuffers(1, &block_starts_);
}

void StoredVertexWeld::weld(unsigned vertices, unsigned indices, long long first, long long count,
                            const std::vector<long long>& block_starts) {
  if (count <= 0) return;
  const long long needed = 2 * count;
  if (needed > slots_ || 4 * needed < slots_) {
    slots_ = needed;
    glNamedBufferData(table_, GLsizeiptr(slots_ * 4), nullptr, GL_DYNAMIC_COPY);
  }
  const GLuint zero = 0;
  glClearNamedBufferSubData(table_, GL_R32UI, 0, GLsizeiptr(needed * 4), GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  std::vector<GLuint> starts(block_starts.begin(), block_starts.end());
  glNamedBufferData(block_starts_, GLsizeiptr(starts.size() * sizeof(GLuint)), starts.data(), GL_STREAM_DRAW);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingStoredVertices, vertices);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingWeldTable, table_);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingStoredIndices, indices);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingBlockStarts, block_starts_);
  program_.use();
  program_.set("u_range_first", int(first));
  program_.set("u_slots", int(needed));
  program_.set("u_blocks", int(starts.size()));
  run_compute_pass(program_, int(count), false, 0);
  glMemoryBarrier(GL_ELEMENT_ARRAY_BARRIER_BIT);
  check_gl_errors("welding the surface cache");
}

}  // namespace gps
