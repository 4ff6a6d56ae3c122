#include "render/dual_stencil_pass.h"

#include <glad/gl.h>

#include "render/compute_limits.h"
#include "render/gl_context.h"
#include "shaders/embedded_shaders.h"

namespace gps {

DualStencilPass::DualStencilPass()
    : dual_map_("dual_map", {{GL_COMPUTE_SHADER, {shaders::gpu_layout, shaders::dual_map_comp}}}),
      stencil_("stencil", {{GL_COMPUTE_SHADER, {shaders::gpu_layout, shaders::stencil_comp}}}) {}

void DualStencilPass::run(int n_base, int vertex_count, int row_count, bool use_list, int group_limit) const {
  dual_map_.use();
  dual_map_.set("u_count", vertex_count);
  dual_map_.set("u_use_list", use_list ? 1 : 0);
  dispatch_split(dual_map_, vertex_count, group_limit);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  stencil_.use();
  stencil_.set("u_count", row_count);
  stencil_.set("u_n_base", n_base);
  stencil_.set("u_use_list", use_list ? 1 : 0);
  dispatch_split(stencil_, row_count, group_limit);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  check_gl_errors("the compute passes");
}

}  // namespace gps
