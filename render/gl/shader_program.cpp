#include "render/gl/shader_program.h"

#include <glad/gl.h>

#include <glm/gtc/type_ptr.hpp>

#include "core/support/error.h"

namespace gps {

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
      std::string line(log);
      line = line.substr(0, line.find('\n'));
      throw Error("shader " + name + " does not compile: " + line);
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
    std::string line(log);
    throw Error("shader " + name + " does not link: " + line.substr(0, line.find('\n')));
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
void ShaderProgram::set(const char* name, const glm::mat4& m) const {
  glProgramUniformMatrix4fv(program_, glGetUniformLocation(program_, name), 1, GL_FALSE, glm::value_ptr(m));
}

}  // namespace gps
