#include "render/gl/gl_context.h"

#include <glad/gl.h>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/osmesa.h>
#include <dlfcn.h>

#include <mutex>
#include <vector>

#include "core/support/error.h"
#include "render/gl/driver_heap.h"

namespace gps {

namespace {

std::mutex debug_mutex;
std::string first_error;

// The first error the driver reports. Not the shader compiler's messages: Mesa reports its warnings
// there as errors, and only while it compiles (not when its shader cache has the program), so they
// would come and go with the cache; a shader that does not compile or link throws in ShaderProgram.
void GLAPIENTRY on_gl_message(GLenum source, GLenum type, GLuint, GLenum severity, GLsizei, const GLchar* message,
                              const void*) {
  if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
  if (type != GL_DEBUG_TYPE_ERROR && severity != GL_DEBUG_SEVERITY_HIGH) return;
  const std::lock_guard lock(debug_mutex);
  if (first_error.empty()) first_error = message;
}

// OSMesa's four entry points, loaded when the first OSMesa context is made: a machine with a GPU
// and EGL runs gpsurf without Mesa's software renderer (and the LLVM it links) installed.
struct OsMesaLibrary {
  decltype(&OSMesaCreateContextAttribs) create = nullptr;
  decltype(&OSMesaMakeCurrent) make_current = nullptr;
  decltype(&OSMesaGetProcAddress) get_proc_address = nullptr;
  decltype(&OSMesaDestroyContext) destroy = nullptr;

  static const OsMesaLibrary& get() {
    static const OsMesaLibrary library = [] {
      OsMesaLibrary l;
      void* handle = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_GLOBAL);
      if (!handle)
        throw Error("OSMesa (libOSMesa.so.8, Debian's libosmesa6) is not installed; on a GPU use --context egl");
      l.create = reinterpret_cast<decltype(l.create)>(dlsym(handle, "OSMesaCreateContextAttribs"));
      l.make_current = reinterpret_cast<decltype(l.make_current)>(dlsym(handle, "OSMesaMakeCurrent"));
      l.get_proc_address = reinterpret_cast<decltype(l.get_proc_address)>(dlsym(handle, "OSMesaGetProcAddress"));
      l.destroy = reinterpret_cast<decltype(l.destroy)>(dlsym(handle, "OSMesaDestroyContext"));
      if (!l.create || !l.make_current || !l.get_proc_address || !l.destroy)
        throw Error("libOSMesa.so.8 lacks the OSMesa 11.2 entry points");
      return l;
    }();
    return library;
  }
};

class OsMesaContext : public GlContext {
public:
  OsMesaContext() : osmesa_(OsMesaLibrary::get()) {
    retain_freed_heap();
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              24,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              4,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              5,
                              0};
    context_ = osmesa_.create(attributes, nullptr);
    if (!context_) throw Error("OSMesa could not create an OpenGL 4.5 core context");
    buffer_.resize(4 * 4 * 4);
    make_current();
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(osmesa_.get_proc_address)))
      throw Error("could not load the OpenGL 4.5 functions through OSMesa");
    enable_gl_debug_output();
  }
  ~OsMesaContext() override { osmesa_.destroy(context_); }
  void make_current() override {
    // OSMesa needs a colour buffer to be current; drawing goes to our framebuffers.
    if (!osmesa_.make_current(context_, buffer_.data(), GL_UNSIGNED_BYTE, 4, 4))
      throw Error("OSMesa could not make its context current");
  }

private:
  const OsMesaLibrary& osmesa_;
  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> buffer_;
};

// A surfaceless EGL context (EGL_KHR_surfaceless_context) on a device or Mesa's surfaceless platform.
class EglContext : public GlContext {
public:
  explicit EglContext(bool require_hardware) {
    retain_freed_heap();  // Mesa's surfaceless platform is llvmpipe too
    const auto get_platform_display =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    const auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    if (!get_platform_display) throw Error("EGL has no eglGetPlatformDisplayEXT");
    if (query_devices) {  // prefer a real device (a GPU driver)
      EGLDeviceEXT devices[8];
      EGLint count = 0;
      if (query_devices(8, devices, &count) && count > 0) {
        for (EGLint i = 0; i < count && display_ == EGL_NO_DISPLAY; ++i) {
          const EGLDisplay d = get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
          EGLint major = 0, minor = 0;
          if (d != EGL_NO_DISPLAY && eglInitialize(d, &major, &minor)) display_ = d;
        }
      }
    }
    if (display_ == EGL_NO_DISPLAY && !require_hardware) {
      display_ = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
      EGLint major = 0, minor = 0;
      if (display_ != EGL_NO_DISPLAY && !eglInitialize(display_, &major, &minor)) display_ = EGL_NO_DISPLAY;
    }
    if (display_ == EGL_NO_DISPLAY) throw Error("no EGL display for a headless OpenGL context");
    const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint n = 0;
    eglBindAPI(EGL_OPENGL_API);
    // Without surfaces a context needs no configuration where EGL_KHR_no_config_context exists.
    if (!eglChooseConfig(display_, config_attributes, &config, 1, &n) || n < 1) config = EGL_NO_CONFIG_KHR;
    const EGLint context_attributes[] = {
        EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, context_attributes);
    if (context_ == EGL_NO_CONTEXT) throw Error("EGL could not create an OpenGL 4.5 core context");
    make_current();
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(eglGetProcAddress)))
      throw Error("could not load the OpenGL 4.5 functions through EGL");
    enable_gl_debug_output();
  }
  ~EglContext() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }
  void make_current() override {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      throw Error("EGL could not make its context current");
  }

private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::string GlContext::description() const {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return std::string(renderer ? renderer : "?") + ", OpenGL " + (version ? version : "?");
}

bool software_renderer() {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const std::string name = renderer ? renderer : "";
  return name.find("llvmpipe") != std::string::npos || name.find("softpipe") != std::string::npos;
}

std::unique_ptr<GlContext> create_offscreen_context(ContextKind kind) {
  switch (kind) {
    case ContextKind::osmesa:
      return std::make_unique<OsMesaContext>();
    case ContextKind::egl:
      return std::make_unique<EglContext>(false);
    case ContextKind::automatic:
      try {
        auto context = std::make_unique<EglContext>(true);
        // Mesa's software device counts as a device too: keep EGL only for a real GPU.
        if (context->description().find("llvmpipe") == std::string::npos) return context;
      } catch (const Error&) {
      }
      return std::make_unique<OsMesaContext>();
  }
  return std::make_unique<OsMesaContext>();
}

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
