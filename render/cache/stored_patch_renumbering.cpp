#include "render/cache/stored_patch_renumbering.h"

#include <glad/gl.h>

#include "render/gl/compute_limits.h"
#include "render/gl/gl_context.h"
#include "render/gl/gpu_layout.h"
#include "shaders/embedded_shaders.h"

namespace gps {

StoredPatchRenumbering::StoredPatchRenumbering()
    : program_("renumber_patches", {{GL_COMPUTE_SHADER, {shaders::gpu_layout, shaders::renumber_patches_comp}}}) {}

void StoredPatchRenumbering::run(unsigned vertices, long long count, const std::vector<int>& new_number) {
  if (count <= 0 || new_number.empty()) return;
  glNamedBufferData(new_number_, GLsizeiptr(new_number.size() * sizeof(int)), new_number.data(), GL_STREAM_DRAW);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingStoredVertices, vertices);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingPatchNumbers, new_number_);
  run_compute_pass(program_, int(count), false, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  check_gl_errors("renumbering the stored patches");
}

}  // namespace gps
