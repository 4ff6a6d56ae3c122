#pragma once
// OpenGL 4.5 core contexts: OSMesa off-screen (no display needed) and, for the editor, GLFW windows.
#include <memory>
#include <string>

namespace gps {

/// A current GL 4.5 core context with the glad loader initialised.
class GlContext {
public:
  virtual ~GlContext() = default;
  virtual void make_current() = 0;
  /// A short description: "OSMesa llvmpipe, OpenGL 4.5 ..." for logs and benchmarks.
  virtual std::string description() const;
};

enum class ContextKind { automatic, osmesa, egl };

/// An off-screen context, rendering into FBOs: OSMesa (Mesa's software llvmpipe, works anywhere) or
/// EGL without a surface (a GPU driver's headless context: EGL_EXT_platform_device, else Mesa's
/// surfaceless platform). `automatic` tries EGL on a GPU device first, then OSMesa.
/// Throws gps::Error when no 4.5 core context can be made.
std::unique_ptr<GlContext> create_offscreen_context(ContextKind kind = ContextKind::osmesa);

/// Whether the current context renders on the CPU (Mesa's llvmpipe or softpipe): there, vertex work is
/// cheap beside rasterising, unlike on a GPU.
bool software_renderer();

/// Turns on KHR_debug and records GL errors; check_gl_errors() throws the first one as gps::Error.
void enable_gl_debug_output();
void check_gl_errors(const char* where);

}  // namespace gps
