#include "render/gl/compute_limits.h"

#include <glad/gl.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "core/support/error.h"
#include "render/gl/gpu_layout.h"

namespace gps {

void dispatch_split(const ShaderProgram& program, int count, int group_limit) {
  GLint max_groups = 0;
  glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &max_groups);
  if (group_limit > 0) max_groups = std::min(max_groups, group_limit);
  const long long per_dispatch = (long long)gpu::kWorkGroupSize * std::max(1, max_groups);
  for (long long first = 0; first < count; first += per_dispatch) {
    program.set("u_first", int(first));
    glDispatchCompute(
        GLuint((std::min<long long>(per_dispatch, count - first) + gpu::kWorkGroupSize - 1) / gpu::kWorkGroupSize), 1,
        1);
  }
}

void run_compute_pass(const ShaderProgram& program, int count, bool use_list, int group_limit) {
  program.use();
  program.set("u_count", count);
  program.set("u_use_list", use_list ? 1 : 0);
  dispatch_split(program, count, group_limit);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void check_storage_fits(const char* what, size_t bytes, int n_vertices, int n_faces, long long limit) {
  GLint64 max_block = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &max_block);
  if (limit > 0) max_block = std::min<GLint64>(max_block, limit);
  const auto size = [](size_t n) {
    char text[32];
    std::snprintf(text, sizeof text, n >= (1u << 20) ? "%.1f MiB" : "%.1f KiB",
                  double(n) / (n >= (1u << 20) ? 1 << 20 : 1 << 10));
    return std::string(text);
  };
  if (max_block > 0 && bytes > size_t(max_block))
    throw Error("the mesh (" + std::to_string(n_vertices) + " vertices, " + std::to_string(n_faces) + " faces) needs " +
                size(bytes) + " of " + what + ", more than the GPU's largest storage buffer (" +
                size(size_t(max_block)) + "); lower the depth or use a smaller mesh");
}

}  // namespace gps
