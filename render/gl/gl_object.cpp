#include "render/gl/gl_object.h"

#include <glad/gl.h>

namespace gps::gl_kind {

unsigned Buffer::create() {
  GLuint name = 0;
  glCreateBuffers(1, &name);
  return name;
}
void Buffer::destroy(unsigned name) { glDeleteBuffers(1, &name); }

unsigned VertexArray::create() {
  GLuint name = 0;
  glCreateVertexArrays(1, &name);
  return name;
}
void VertexArray::destroy(unsigned name) { glDeleteVertexArrays(1, &name); }

unsigned Framebuffer::create() {
  GLuint name = 0;
  glCreateFramebuffers(1, &name);
  return name;
}
void Framebuffer::destroy(unsigned name) { glDeleteFramebuffers(1, &name); }

unsigned Renderbuffer::create() {
  GLuint name = 0;
  glCreateRenderbuffers(1, &name);
  return name;
}
void Renderbuffer::destroy(unsigned name) { glDeleteRenderbuffers(1, &name); }

unsigned Texture::create(unsigned target) {
  GLuint name = 0;
  glCreateTextures(target, 1, &name);
  return name;
}
void Texture::destroy(unsigned name) { glDeleteTextures(1, &name); }

unsigned Query::create() {
  GLuint name = 0;
  glGenQueries(1, &name);
  return name;
}
unsigned Query::create(unsigned target) {
  GLuint name = 0;
  glCreateQueries(target, 1, &name);
  return name;
}
void Query::destroy(unsigned name) { glDeleteQueries(1, &name); }

unsigned Shader::create(unsigned type) { return glCreateShader(type); }
void Shader::destroy(unsigned name) { glDeleteShader(name); }

unsigned Program::create() { return glCreateProgram(); }
void Program::destroy(unsigned name) { glDeleteProgram(name); }

}  // namespace gps::gl_kind
