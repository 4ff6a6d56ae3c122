#include "render/gl_context.h"

#include <glad/gl.h>

#include <GL/osmesa.h>

#include <mutex>
#include <vector>

#include "core/error.h"

namespace gps {

namespace {

std::mutex debug_mutex;
std::string first_error;

void GLAPIENTRY on_gl_message(GLenum, GLenum type, GLuint, GLenum severity, GLsizei, const GLchar* message, const void*) {
  if (type != GL_DEBUG_TYPE_ERROR && severity != GL_DEBUG_SEVERITY_HIGH) return;
  const std::lock_guard lock(debug_mutex);
  if (first_error.empty()) first_error = message;
}

class OsMesaContext : public GlContext {
public:
  OsMesaContext() {
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!context_) throw Error("OSMesa could not create an OpenGL 4.5 core context");
    buffer_.resize(4 * 4 * 4);
    make_current();
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(OSMesaGetProcAddress)))
      throw Error("could not load the OpenGL 4.5 functions through OSMesa");
    enable_gl_debug_output();
  }
  ~OsMesaContext() override { OSMesaDestroyContext(context_); }
  void make_current() override {
    // OSMesa needs a colour buffer to be current; drawing goes to our framebuffers.
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 4, 4)) throw Error("OSMesa could not make its context current");
  }

private:
  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> buffer_;
};

}  // namespace

std::string GlContext::description() const {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return std::string(renderer ? renderer : "?") + ", OpenGL " + (version ? version : "?");
}

std::unique_ptr<GlContext> create_offscreen_context() { return std::make_unique<OsMesaContext>(); }

void enable_gl_debug_output() {
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(on_gl_message, nullptr);
}

void check_gl_errors(const char* where) {
  std::string message;
  {
    const std::lock_guard lock(debug_mutex);
    message.swap(first_error);
  }
  if (const GLenum e = glGetError(); message.empty() && e != GL_NO_ERROR) message = "error code " + std::to_string(e);
  while (glGetError() != GL_NO_ERROR) {
  }
  if (!message.empty()) throw Error(std::string("OpenGL error in ") + where + ": " + message);
}

}  // namespace gps
