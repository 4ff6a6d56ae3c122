#pragma once
// A linked GLSL program from sources (shaders/ embedded at build time).
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace gps {

struct ShaderStage {
  unsigned type;                     // GL_VERTEX_SHADER, ...
  std::vector<const char*> sources;  // concatenated after the #version line
};

class ShaderProgram {
public:
  ShaderProgram() = default;
  /// Compiles and links; `name` appears in the one-line error if the driver refuses it.
  /// `feedback` names varyings captured by transform feedback (interleaved).
  ShaderProgram(const std::string& name, const std::vector<ShaderStage>& stages,
                const std::vector<const char*>& feedback = {});
  ~ShaderProgram();
  ShaderProgram(ShaderProgram&& other) noexcept;
  ShaderProgram& operator=(ShaderProgram&& other) noexcept;

  unsigned id() const { return id_; }
  void use() const;
  void set(const char* name, int value) const;
  void set(const char* name, float value) const;
  void set(const char* name, const glm::vec2& value) const;
  void set(const char* name, const glm::vec4& value) const;
  void set(const char* name, const glm::mat4& value) const;

private:
  unsigned id_ = 0;
};

}  // namespace gps
