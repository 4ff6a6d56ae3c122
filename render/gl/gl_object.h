#pragma once
// The owner of one OpenGL object name: the object is created with the owner (the glCreate* call;
// glGenQueries for a query without a target) and deleted with it; an owner moves but is not copied,
// and a moved-from one holds name 0. It converts to the name (GLuint), so GL calls take it as they
// take the name.
#include <utility>

namespace gps {

/// How each kind of GL object is created and deleted (render/gl/gl_object.cpp); a GL context must be
/// current for either.
namespace gl_kind {
struct Buffer {
  static unsigned create();
  static void destroy(unsigned name);
};
struct VertexArray {
  static unsigned create();
  static void destroy(unsigned name);
};
struct Framebuffer {
  static unsigned create();
  static void destroy(unsigned name);
};
struct Renderbuffer {
  static unsigned create();
  static void destroy(unsigned name);
};
/// Of a target: GL_TEXTURE_2D, ...
struct Texture {
  static unsigned create(unsigned target);
  static void destroy(unsigned name);
};
/// Of a target (GL_TIME_ELAPSED, ...), or without one: a name whose first glBeginQuery gives it its
/// target (glGenQueries; Mesa 22.3's glCreateQueries refuses the pipeline-statistics targets).
struct Query {
  static unsigned create();
  static unsigned create(unsigned target);
  static void destroy(unsigned name);
};
/// Of a stage: GL_VERTEX_SHADER, ...
struct Shader {
  static unsigned create(unsigned type);
  static void destroy(unsigned name);
};
struct Program {
  static unsigned create();
  static void destroy(unsigned name);
};
}  // namespace gl_kind

template <class Kind>
class GlObject {
public:
  /// Creates the object (the kinds that need no target).
  GlObject() : name_(Kind::create()) {}
  /// Creates the object of `target` (a query's or texture's target, a shader's stage).
  explicit GlObject(unsigned target) : name_(Kind::create(target)) {}
  /// No object (name 0), as a moved-from owner holds: for one created later and assigned.
  static GlObject none() { return GlObject(None{}); }

  ~GlObject() {
    if (name_ != 0) Kind::destroy(name_);
  }
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;
  GlObject(GlObject&& other) noexcept : name_(std::exchange(other.name_, 0u)) {}
  /// Deletes the object held, then takes `other`'s.
  GlObject& operator=(GlObject&& other) noexcept {
    if (this != &other) {
      if (name_ != 0) Kind::destroy(name_);
      name_ = std::exchange(other.name_, 0u);
    }
    return *this;
  }

  /// The object's name (0: none), for GL calls.
  unsigned get() const { return name_; }
  operator unsigned() const { return name_; }

private:
  struct None {};
  explicit GlObject(None) : name_(0) {}

  unsigned name_;
};

using GlBuffer = GlObject<gl_kind::Buffer>;
using GlVertexArray = GlObject<gl_kind::VertexArray>;
using GlFramebuffer = GlObject<gl_kind::Framebuffer>;
using GlRenderbuffer = GlObject<gl_kind::Renderbuffer>;
using GlTexture = GlObject<gl_kind::Texture>;
using GlQuery = GlObject<gl_kind::Query>;
using GlShader = GlObject<gl_kind::Shader>;
using GlProgram = GlObject<gl_kind::Program>;

}  // namespace gps
