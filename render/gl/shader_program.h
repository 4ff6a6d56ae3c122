#pragma once
// A linked GLSL program from sources (shaders/ embedded at build time).
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "render/gl/gl_object.h"

namespace gps {

struct ShaderStage {
  unsigned type;                     // GL_VERTEX_SHADER, ...
  std::vector<const char*> sources;  // concatenated after the #version line
};

class ShaderProgram {
public:
  /// No program (id 0).
  ShaderProgram() = default;
  /// Compiles and links; `name` appears in the one-line error if the driver refuses it.
  /// `feedback` names varyings captured by transform feedback (interleaved).
  ShaderProgram(const std::string& name, const std::vector<ShaderStage>& stages,
                const std::vector<const char*>& feedback = {});
  ShaderProgram(ShaderProgram&& other) noexcept = default;
  ShaderProgram& operator=(ShaderProgram&& other) noexcept = default;

  unsigned id() const { return program_; }
  void use() const;
  void set(const char* name, int value) const;
  void set(const char* name, float value) const;
  void set(const char* name, const glm::vec2& value) const;
  void set(const char* name, const glm::vec3& value) const;
  void set(const char* name, const glm::vec4& value) const;
  void set(const char* name, const glm::mat3& value) const;
  void set(const char* name, const glm::mat4& value) const;

private:
  GlProgram program_ = GlProgram::none();
};

}  // namespace gps
