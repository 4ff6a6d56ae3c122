#include "render/cache/patch_triangle_counts.h"

#include <glad/gl.h>

#include "render/gl/compute_limits.h"
#include "render/gl/gl_context.h"
#include "render/gl/gpu_layout.h"
#include "shaders/embedded_shaders.h"

namespace gps {

PatchTriangleCounts::PatchTriangleCounts()
    : programs_(plan_compute_programs("patch_triangle_count", false,
                                      {shaders::tess_levels, shaders::patch_triangle_count_comp})) {}

void PatchTriangleCounts::set_precision(PointPrecision precision) { programs_.set_precision(precision, false); }

std::vector<int> PatchTriangleCounts::count(PatchShape shape, const std::vector<int>& patches, int group_limit) {
  if (patches.empty()) return {};
  std::vector<int> counts(patches.size(), 0);
  glNamedBufferData(patches_, GLsizeiptr(patches.size() * sizeof(GLint)), patches.data(), GL_STREAM_DRAW);
  glNamedBufferData(counts_, GLsizeiptr(counts.size() * sizeof(GLint)), nullptr, GL_STREAM_READ);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingCountedPatches, patches_);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingPatchTriangles, counts_);
  run_compute_pass(program(shape), int(patches.size()), true, group_limit);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(counts_, 0, GLsizeiptr(counts.size() * sizeof(GLint)), counts.data());
  check_gl_errors("counting the patches' triangles");
  return counts;
}

}  // namespace gps
