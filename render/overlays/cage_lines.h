#pragma once
// The base mesh drawn as thin grey lines over the surface: full strength where in front of it,
// faint (kHiddenCageAlpha) where behind.
#include <glm/glm.hpp>
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "render/gl/gl_object.h"
#include "render/gl/render_target.h"
#include "render/gl/shader_program.h"

namespace gps {

class CageLines {
public:
  /// Needs a current GL 4.5 context.
  CageLines();
  CageLines(const CageLines&) = delete;
  CageLines& operator=(const CageLines&) = delete;

  /// The mesh's edges and its vertices' `positions` (one per vertex). The buffers keep their storage
  /// where the mesh fits in it, as after a modelling operation.
  void set_mesh(const CovarianceMesh& mesh, const std::vector<glm::vec3>& positions);
  /// Every vertex position.
  void upload_positions(const std::vector<glm::vec3>& positions);
  /// The `changed` vertices' positions.
  void update_positions(const std::vector<glm::vec3>& positions, const std::vector<int>& changed);
  bool empty() const { return index_count_ == 0; }
  /// Over the surface already drawn into `target` (its depth), into the colour attachment only;
  /// without the edges `hidden_edges` marks 1 (by edge index) where given.
  void draw(const RenderTarget& target, const glm::mat4& view_projection,
            const std::vector<char>* hidden_edges = nullptr) const;

private:
  ShaderProgram program_;
  GlVertexArray vao_;
  GlBuffer vbo_, ibo_;  // base vertex positions, edges as index pairs
  size_t vbo_bytes_ = 0, ibo_bytes_ = 0;  // the storage they hold
  int index_count_ = 0;
};

}  // namespace gps
