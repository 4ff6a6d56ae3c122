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

namespace {

// `bytes` of `data` into `buffer`, whose storage (`capacity` bytes) stays where they fit in it and it is
// not twice as large: a modelling operation's mesh is written over the one before it, not into storage
// the driver allocates (and clears) again. An empty upload keeps a little storage to bind.
void write_buffer(GLuint buffer, size_t& capacity, const void* data, size_t bytes) {
  const size_t needed = std::max<size_t>(bytes, 16);
  if (needed > capacity || capacity / 2 > needed) {
    capacity = needed + needed / 16;  // room for the vertices and edges an operation adds
    glNamedBufferData(buffer, GLsizeiptr(capacity), nullptr, GL_DYNAMIC_DRAW);
  }
  if (bytes > 0) glNamedBufferSubData(buffer, 0, GLsizeiptr(bytes), data);
}

}  // namespace

void CageLines::set_mesh(const CovarianceMesh& mesh, const std::vector<glm::vec3>& positions) {
  // The edges' ends as they are: vertex indices are never negative, so their ints are the unsigned
  // indices the draw reads.
  const std::vector<int>& ends = mesh.connectivity().edge_verts;
  static_assert(sizeof(int) == sizeof(GLuint));
  index_count_ = int(ends.size());
  upload_positions(positions);
  write_buffer(ibo_, ibo_bytes_, ends.data(), ends.size() * sizeof(GLuint));
}

void CageLines::upload_positions(const std::vector<glm::vec3>& positions) {
  static_assert(sizeof(glm::vec3) == 3 * sizeof(float));
  write_buffer(vbo_, vbo_bytes_, positions.data(), positions.size() * sizeof(glm::vec3));
}

void CageLines::update_positions(const std::vector<glm::vec3>& positions, const std::vector<int>& changed) {
  for (const int v : changed)
    glNamedBufferSubData(vbo_, GLintptr(sizeof(glm::vec3) * size_t(v)), sizeof(glm::vec3), &positions[size_t(v)]);
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
