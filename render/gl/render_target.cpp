#include "render/gl/render_target.h"

#include <glad/gl.h>

#include <atomic>

#include "core/support/error.h"
#include "render/gl/gl_context.h"

namespace gps {

namespace {

// The width, once both sides are checked: before any GL object is made.
int checked_width(int width, int height) {
  if (width < 1 || height < 1 || width > RenderTarget::kLargestSide || height > RenderTarget::kLargestSide)
    throw usage_error("image size must be 1.." + std::to_string(RenderTarget::kLargestSide) + " pixels each way, got " +
                      std::to_string(width) + "x" + std::to_string(height));
  return width;
}

std::uint64_t next_serial() {
  static std::atomic<std::uint64_t> last{0};
  return ++last;
}

}  // namespace

RenderTarget::RenderTarget(int width, int height)
    : width_(checked_width(width, height)),
      height_(height),
      serial_(next_serial()),
      textures_{GlTexture(GL_TEXTURE_2D), GlTexture(GL_TEXTURE_2D), GlTexture(GL_TEXTURE_2D)} {
  const GLenum formats[3] = {GL_RGBA8, GL_RGBA32F, GL_RGBA32F};
  for (int i = 0; i < 3; ++i) {
    glTextureStorage2D(textures_[i], 1, formats[i], width, height);
    glNamedFramebufferTexture(fbo_, GLenum(GL_COLOR_ATTACHMENT0 + i), textures_[i], 0);
  }
  glNamedRenderbufferStorage(depth_, GL_DEPTH_COMPONENT32F, width, height);
  glNamedFramebufferRenderbuffer(fbo_, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  set_colour_only(false);
  if (glCheckNamedFramebufferStatus(fbo_, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw Error("the off-screen framebuffer is incomplete");
  check_gl_errors("creating the render target");
}

void RenderTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, width_, height_);
}

void RenderTarget::set_colour_only(bool colour_only) const {
  const GLenum colour[3] = {GL_COLOR_ATTACHMENT0, GL_NONE, GL_NONE},
               all[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
  glNamedFramebufferDrawBuffers(fbo_, 3, colour_only ? colour : all);
}

Image RenderTarget::read(int attachment) const {
  Image image{width_, height_, 4, std::vector<float>(size_t(width_) * size_t(height_) * 4)};
  glNamedFramebufferReadBuffer(fbo_, GLenum(GL_COLOR_ATTACHMENT0 + attachment));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, image.pixels.data());
  check_gl_errors("reading the render target");
  flip_rows(image);
  return image;
}

}  // namespace gps
