#pragma once
// The covariance ellipsoids (thesis Fig. 1.1): per vertex three unit circles mapped by [Σ^½ | μ],
// instanced; uploaded once per mesh, then only the changed vertices per edit.
#include <glm/glm.hpp>
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "render/gl/normalised_frame.h"
#include "render/gl/gl_object.h"
#include "render/gl/shader_program.h"

namespace gps {

class EllipsoidOverlay {
public:
  /// Needs a current GL 4.5 context.
  EllipsoidOverlay();
  EllipsoidOverlay(const EllipsoidOverlay&) = delete;
  EllipsoidOverlay& operator=(const EllipsoidOverlay&) = delete;

  /// Every vertex's ellipsoid (`changed` null), or only those of `changed`.
  void upload(const FramedGaussians& gaussians, const std::vector<int>* changed);
  /// The k-σ ellipsoids as lines in the current framebuffer: every vertex's (`only` null) or
  /// those of the vertices in `only` (ascending; one indirect draw, a command per run of indices).
  void draw(const glm::mat4& view_projection, float sigma, const std::vector<int>* only = nullptr);

private:
  ShaderProgram program_;
  GlVertexArray vao_;
  GlBuffer circle_vbo_, instance_vbo_, indirect_;
  int circle_vertex_count_ = 0;
  int count_ = 0;  // instances: per vertex a mat4 [Σ^½ | μ] (k-σ in the shader)
};

}  // namespace gps
