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

/// An off-screen context through Mesa's OSMesa (software, llvmpipe); renders into FBOs.
/// Throws gps::Error when no 4.5 core context can be made.
std::unique_ptr<GlContext> create_offscreen_context();

/// Turns on KHR_debug and records GL errors; check_gl_errors() throws the first one as gps::Error.
void enable_gl_debug_output();
void check_gl_errors(const char* where);

}  // namespace gps
