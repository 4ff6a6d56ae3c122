#include "render/gl/shader_program.h"

#include <glad/gl.h>

#include <glm/gtc/type_ptr.hpp>

#include "core/mesh/error.h"

namespace gps {

ShaderProgram::ShaderProgram(const std::string& name, const std::vector<ShaderStage>& stages,
                             const std::vector<const char*>& feedback) {
  id_ = glCreateProgram();
  std::vector<GLuint> shaders;
  for (const auto& stage : stages) {
    std::vector<const char*> sources = {"#version 450 core\n"};
    sources.insert(sources.end(), stage.sources.begin(), stage.sources.end());
    const GLuint s = glCreateShader(stage.type);
    glShaderSource(s, GLsizei(sources.size()), sources.data(), nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      char log[2048] = {};
      glGetShaderInfoLog(s, sizeof log - 1, nullptr, log);
      std::string line(log);
      line = line.substr(0, line.find('\n'));
      glDeleteShader(s);
      throw Error("shader " + name + " does not compile: " + line);
    }
    glAttachShader(id_, s);
    shaders.push_back(s);
  }
  if (!feedback.empty())
    glTransformFeedbackVaryings(id_, GLsizei(feedback.size()), feedback.data(), GL_INTERLEAVED_ATTRIBS);
  glLinkProgram(id_);
  for (const GLuint s : shaders) glDeleteShader(s);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetProgramInfoLog(id_, sizeof log - 1, nullptr, log);
    std::string line(log);
    throw Error("shader " + name + " does not link: " + line.substr(0, line.find('\n')));
  }
}

ShaderProgram::~ShaderProgram() {
  if (id_) glDeleteProgram(id_);
}

ShaderProgram::ShaderProgram(ShaderProgram&& other) noexcept : id_(other.id_) { other.id_ = 0; }

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& other) noexcept {
  std::swap(id_, other.id_);
  return *this;
}

void ShaderProgram::use() const { glUseProgram(id_); }
void ShaderProgram::set(const char* name, int value) const {
  glProgramUniform1i(id_, glGetUniformLocation(id_, name), value);
}
void ShaderProgram::set(const char* name, float value) const {
  glProgramUniform1f(id_, glGetUniformLocation(id_, name), value);
}
void ShaderProgram::set(const char* name, const glm::vec2& v) const {
  glProgramUniform2fv(id_, glGetUniformLocation(id_, name), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const char* name, const glm::vec4& v) const {
  glProgramUniform4fv(id_, glGetUniformLocation(id_, name), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const char* name, const glm::mat4& m) const {
  glProgramUniformMatrix4fv(id_, glGetUniformLocation(id_, name), 1, GL_FALSE, glm::value_ptr(m));
}

}  // namespace gps
