#include "render/pipeline/patch_level_bound.h"

#include <glad/gl.h>

#include <algorithm>

#include "render/gl/compute_limits.h"
#include "render/gl/gl_context.h"
#include "render/gl/gpu_layout.h"
#include "shaders/embedded_shaders.h"

namespace gps {

namespace {

// Copies the float uniforms `name` (of `count` floats) of program `from` into program `to`.
void copy_uniform(unsigned from, unsigned to, const char* name, int count) {
  float values[16] = {};
  glGetUniformfv(from, glGetUniformLocation(from, name), values);
  const int location = glGetUniformLocation(to, name);
  if (count == 16)
    glProgramUniformMatrix4fv(to, location, 1, GL_FALSE, values);
  else if (count == 2)
    glProgramUniform2fv(to, location, 1, values);
  else
    glProgramUniform1f(to, location, values[0]);
}

}  // namespace

PatchLevelBound::PatchLevelBound()
    : programs_(
          plan_compute_programs("patch_level_bound", false, {shaders::tess_levels, shaders::patch_level_bound_comp})) {
  glNamedBufferData(result_, sizeof(GLuint), nullptr, GL_DYNAMIC_READ);
}

void PatchLevelBound::set_precision(PointPrecision precision) { programs_.set_precision(precision); }

int PatchLevelBound::max_level(PatchShape shape, const ShaderProgram& draw_program, int first_patch,
                               int n_patches) const {
  if (n_patches <= 0) return 1;
  // A capture's draws run inside transform feedback, where only a paused session lets another
  // program be used.
  GLboolean feedback = GL_FALSE, paused = GL_FALSE;
  glGetBooleanv(GL_TRANSFORM_FEEDBACK_ACTIVE, &feedback);
  glGetBooleanv(GL_TRANSFORM_FEEDBACK_PAUSED, &paused);
  const bool pause = feedback && !paused;
  if (pause) glPauseTransformFeedback();
  const ShaderProgram& program = programs_(shape);
  const unsigned from = draw_program.id(), to = program.id();
  copy_uniform(from, to, "u_view_projection", 16);
  copy_uniform(from, to, "u_viewport", 2);
  copy_uniform(from, to, "u_level", 1);
  copy_uniform(from, to, "u_pixels", 1);
  GLint mismatch = 0;
  glGetUniformiv(from, glGetUniformLocation(from, "u_debug_mismatch"), &mismatch);
  program.set("u_debug_mismatch", mismatch);
  program.set("u_first_bound_patch", first_patch);
  const GLuint zero = 0;
  glNamedBufferSubData(result_, 0, sizeof zero, &zero);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingLevelBound, result_);
  run_compute_pass(program, n_patches, false, 0);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  GLuint level = 0;
  glGetNamedBufferSubData(result_, 0, sizeof level, &level);
  draw_program.use();
  if (pause) glResumeTransformFeedback();
  check_gl_errors("bounding the patches' tessellation levels");
  return std::clamp(int(level), 1, 64);
}

}  // namespace gps
