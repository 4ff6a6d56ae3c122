#include "render/pipeline/dual_stencil_pass.h"

#include <glad/gl.h>

#include "render/gl/compute_limits.h"
#include "render/gl/gl_context.h"
#include "shaders/embedded_shaders.h"

namespace gps {

DualStencilPass::DualStencilPass() { set_precision(PointPrecision::single_float); }

void DualStencilPass::set_precision(PointPrecision precision) {
  const int i = int(precision);
  if (stencil_[i].id() == 0) {  // the last one built, before the switch
    dual_map_[i] = ShaderProgram(
        "dual_map", at_precision({{GL_COMPUTE_SHADER, {shaders::gpu_layout, shaders::dual_map_comp}}}, precision));
    stencil_[i] = ShaderProgram(
        "stencil", at_precision({{GL_COMPUTE_SHADER, {shaders::gpu_layout, shaders::stencil_comp}}}, precision));
  }
  precision_ = precision;
}

void DualStencilPass::run(int first_row, int vertex_count, int row_count, bool list_vertices, bool list_rows,
                          int group_limit) const {
  const ShaderProgram &dual_map = dual_map_[int(precision_)], &stencil = stencil_[int(precision_)];
  run_compute_pass(dual_map, vertex_count, list_vertices, group_limit);
  stencil.use();
  stencil.set("u_first_row", first_row);
  run_compute_pass(stencil, row_count, list_rows, group_limit);
  check_gl_errors("the compute passes");
}

}  // namespace gps
