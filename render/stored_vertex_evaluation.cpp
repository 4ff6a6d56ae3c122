#include "render/stored_vertex_evaluation.h"

#include <glad/gl.h>

#include "render/gl_context.h"
#include "shaders/embedded_shaders.h"

namespace gps {

StoredVertexEvaluation::StoredVertexEvaluation()
    : quads_("stored_vertex_evaluation", {{GL_COMPUTE_SHADER,
                                           {shaders::gpu_layout, shaders::patch_basis, shaders::plan_eval,
                                            shaders::stored_vertex_evaluation_comp}}}),
      triangles_("stored_vertex_evaluation_triangles",
                 {{GL_COMPUTE_SHADER,
                   {"#define GPS_TRIANGLE_PATCHES\n", shaders::gpu_layout, shaders::patch_basis, shaders::plan_eval, shaders::loop_eval,
                    shaders::stored_vertex_evaluation_comp}}}) {}

void StoredVertexEvaluation::run(PatchShape shape, long long first, long long bound, long long dispatch_offset) const {
  if (bound <= 0) return;
  const ShaderProgram& program = shape == PatchShape::triangle ? triangles_ : quads_;
  program.use();
  program.set("u_range_first", int(first));
  program.set("u_count", int(bound));
  program.set("u_first", 0);
  program.set("u_use_list", 0);
  glDispatchComputeIndirect(GLintptr(dispatch_offset));
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  check_gl_errors("evaluating the stored vertices");
}

}  // namespace gps
