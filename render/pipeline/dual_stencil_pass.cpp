#include "render/pipeline/dual_stencil_pass.h"

#include <glad/gl.h>

#include "render/gl/compute_limits.h"
#include "render/gl/gl_context.h"
#include "shaders/embedded_shaders.h"

namespace gps {

DualStencilPass::DualStencilPass()
    : dual_map_("dual_map", {{GL_COMPUTE_SHADER, {shaders::gpu_layout, shaders::dual_map_comp}}}),
      stencil_("stencil", {{GL_COMPUTE_SHADER, {shaders::gpu_layout, shaders::stencil_comp}}}) {}

void DualStencilPass::run(int n_base, int vertex_count, int row_count, bool use_list, int group_limit) const {
  run_compute_pass(dual_map_, vertex_count, use_list, group_limit);
  stencil_.use();
  stencil_.set("u_n_base", n_base);
  run_compute_pass(stencil_, row_count, use_list, group_limit);
  check_gl_errors("the compute passes");
}

}  // namespace gps
