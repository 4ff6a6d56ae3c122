#include "render/pipeline/surface_point.h"

#include <glad/gl.h>

#include <cmath>

#include "render/gl/gl_context.h"

namespace gps {

std::optional<glm::vec3> surface_point(const RenderTarget& target, glm::vec2 pixel) {
  const int x = int(std::floor(pixel.x)), y = int(std::floor(pixel.y));
  if (x < 0 || y < 0 || x >= target.width() || y >= target.height()) return std::nullopt;
  float value[4] = {0, 0, 0, 0};
  glNamedFramebufferReadBuffer(target.framebuffer(), GL_COLOR_ATTACHMENT1);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, target.framebuffer());
  glReadPixels(x, target.height() - 1 - y, 1, 1, GL_RGBA, GL_FLOAT, value);
  check_gl_errors("reading the position under a pixel");
  if (value[3] < 0.5f) return std::nullopt;
  return glm::vec3(value[0], value[1], value[2]);
}

}  // namespace gps
