#include "render/overlays/cage_lines.h"

#include <glad/gl.h>

#include <algorithm>
#include <utility>

#include "render/gl/draw_options.h"
#include "render/gl/gl_context.h"
#include "shaders/embedded_shaders.h"

namespace gps {

CageLines::CageLines()
    : program_("lines", {{GL_VERTEX_SHADER, {shaders::lines_vert}}, {GL_FRAGMENT_SHADER, {shaders::lines_frag}}}) {
  glVertexArrayVertexBuffer(vao_, 0, vbo_, 0, 3 * sizeof(float));
  glVertexArrayElementBuffer(vao_, ibo_);
  glEnableVertexArrayAttrib(vao_, 0);
  glVertexArrayAttribFormat(vao_, 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao_, 0, 0);
}

void CageLines::set_mesh(const CovarianceMesh& mesh, const FramedGaussians& gaussians) {
  // The edges' ends as they are: vertex indices are never negative, so their ints are the unsigned
  // indices the draw reads.
  const std::vector<int>& ends = mesh.connectivity().edge_verts;
  static_assert(sizeof(int) == sizeof(GLuint));
  index_count_ = int(ends.size());
  upload_positions(gaussians);
  const int none[2] = {0, 0};
  glNamedBufferData(ibo_, GLsizeiptr(std::max<size_t>(2, ends.size()) * sizeof(GLuint)),
                    ends.empty() ? none : ends.data(), GL_STATIC_DRAW);
}

void CageLines::upload_positions(const FramedGaussians& gaussians) {
  std::vector<float> positions(3 * gaussians.n_vertices());
  for (size_t i = 0; i < gaussians.n_vertices(); ++i)
    for (int k = 0; k < 3; ++k) positions[3 * i + size_t(k)] = float(gaussians.mean(i)[k]);
  glNamedBufferData(vbo_, GLsizeiptr(std::max<size_t>(3, positions.size()) * sizeof(float)), positions.data(),
                    GL_DYNAMIC_DRAW);
}

void CageLines::update_positions(const FramedGaussians& gaussians, const std::vector<int>& changed) {
  for (const int v : changed) {
    const Vec3 m = gaussians.mean(size_t(v));
    const float position[3] = {float(m.x()), float(m.y()), float(m.z())};
    glNamedBufferSubData(vbo_, GLintptr(3 * sizeof(float) * size_t(v)), sizeof position, position);
  }
}

void CageLines::draw(const RenderTarget& target, const glm::mat4& view_projection,
                     const std::vector<char>* hidden_edges) const {
  program_.set("u_view_projection", view_projection);
  program_.use();
  target.set_colour_only(true);
  glBindVertexArray(vao_);
  // The runs [first, end) of edges shown (edge e is indices 2e, 2e + 1): all, or those not hidden.
  const int n_edges = index_count_ / 2;
  const auto is_hidden = [&](int e) {
    return hidden_edges && size_t(e) < hidden_edges->size() && (*hidden_edges)[size_t(e)];
  };
  std::vector<std::pair<int, int>> runs;
  for (int first = 0; first < n_edges;) {
    if (is_hidden(first)) {
      ++first;
      continue;
    }
    int end = first;
    while (end < n_edges && !is_hidden(end)) ++end;
    runs.emplace_back(first, end);
    first = end;
  }
  glDepthMask(GL_FALSE);  // the cage with depth: its parts behind the surface faint, the others full
  glEnablei(GL_BLEND, 0);
  glBlendFuncSeparatei(0, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);  // the image's alpha kept
  for (const bool hidden : {true, false}) {
    glDepthFunc(hidden ? GL_GREATER : GL_LEQUAL);
    program_.set("u_color", glm::vec4(0.45f, 0.45f, 0.45f, hidden ? kHiddenCageAlpha : 1.0f));
    for (const auto& [first, end] : runs)
      glDrawElements(GL_LINES, 2 * (end - first), GL_UNSIGNED_INT,
                     reinterpret_cast<const void*>(2 * size_t(first) * sizeof(unsigned)));
  }
  glDisablei(GL_BLEND, 0);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LEQUAL);
  target.set_colour_only(false);
}

}  // namespace gps
