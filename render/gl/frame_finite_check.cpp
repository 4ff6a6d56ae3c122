#include "render/gl/frame_finite_check.h"

#include <glad/gl.h>

#include "render/gl/gl_context.h"
#include "shaders/embedded_shaders.h"

namespace gps {

namespace {
constexpr int kTile = 16;  // shaders/non_finite_count_comp.glsl's work group is kTile × kTile pixels
}

FrameFiniteCheck::FrameFiniteCheck()
    : program_("non_finite_count", {{GL_COMPUTE_SHADER, {shaders::non_finite_count_comp}}}) {
  glNamedBufferStorage(count_, sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

long long FrameFiniteCheck::non_finite_pixels(const RenderTarget& target) const {
  const GLuint zero = 0;
  glNamedBufferSubData(count_, 0, sizeof zero, &zero);
  glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, 0, count_);
  glBindImageTexture(0, target.texture(1), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
  glBindImageTexture(1, target.texture(2), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
  program_.use();
  glDispatchCompute(GLuint((target.width() + kTile - 1) / kTile), GLuint((target.height() + kTile - 1) / kTile), 1);
  glMemoryBarrier(GL_ATOMIC_COUNTER_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  GLuint count = 0;
  glGetNamedBufferSubData(count_, 0, sizeof count, &count);
  for (GLuint unit : {0u, 1u}) glBindImageTexture(unit, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
  check_gl_errors("counting the frame's pixels that are not finite");
  return count;
}

}  // namespace gps
