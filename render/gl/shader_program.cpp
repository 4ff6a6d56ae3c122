#include "render/gl/shader_program.h"

#include <glad/gl.h>

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>

#include "core/support/error.h"

namespace gps {

namespace {
// The line of a driver's info log that says what is wrong: the first that names an error (NVIDIA's
// logs open with a heading such as "Compute info"), else the first that is not empty.
std::string first_error_line(const char* log) {
  std::string text(log), first;
  for (size_t start = 0; start < text.size();) {
    const size_t end = std::min(text.find('\n', start), text.size());
    const std::string line = text.substr(start, end - start);
    if (line.find("error") != std::string::npos || line.find("ERROR") != std::string::npos) return line;
    if (first.empty() && line.find_first_not_of(" \t\r-") != std::string::npos) first = line;
    start = end + 1;
  }
  return first;
}
}  // namespace

ShaderProgram::ShaderProgram(const std::string& name, const std::vector<ShaderStage>& stages,
                             const std::vector<const char*>& feedback)
    : program_() {
  std::vector<GlShader> shaders;
  for (const auto& stage : stages) {
    std::vector<const char*> sources = {"#version 450 core\n"};
    sources.insert(sources.end(), stage.sources.begin(), stage.sources.end());
    GlShader s(stage.type);
    glShaderSource(s, GLsizei(sources.size()), sources.data(), nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      char log[2048] = {};
      glGetShaderInfoLog(s, sizeof log - 1, nullptr, log);
      throw Error("shader " + name + " does not compile: " + first_error_line(log));
    }
    glAttachShader(program_, s);
    shaders.push_back(std::move(s));
  }
  if (!feedback.empty())
    glTransformFeedbackVaryings(program_, GLsizei(feedback.size()), feedback.data(), GL_INTERLEAVED_ATTRIBS);
  glLinkProgram(program_);
  shaders.clear();  // deleted once the program is linked
  GLint ok = 0;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetProgramInfoLog(program_, sizeof log - 1, nullptr, log);
    throw Error("shader " + name + " does not link: " + first_error_line(log));
  }
}

void ShaderProgram::use() const { glUseProgram(program_); }
void ShaderProgram::set(const char* name, int value) const {
  glProgramUniform1i(program_, glGetUniformLocation(program_, name), value);
}
void ShaderProgram::set(const char* name, float value) const {
  glProgramUniform1f(program_, glGetUniformLocation(program_, name), value);
}
void ShaderProgram::set(const char* name, const glm::vec2& v) const {
  glProgramUniform2fv(program_, glGetUniformLocation(program_, name), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const char* name, const glm::vec3& v) const {
  glProgramUniform3fv(program_, glGetUniformLocation(program_, name), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const char* name, const glm::vec4& v) const {
  glProgramUniform4fv(program_, glGetUniformLocation(program_, name), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const char* name, const glm::mat3& m) const {
  glProgramUniformMatrix3fv(program_, glGetUniformLocation(program_, name), 1, GL_FALSE, glm::value_ptr(m));
}
void ShaderProgram::set(const char* name, const glm::mat4& m) const {
  glProgramUniformMatrix4fv(program_, glGetUniformLocation(program_, name), 1, GL_FALSE, glm::value_ptr(m));
}

}  // namespace gps
