#include "render/overlays/vertex_dots.h"

#include <glad/gl.h>

#include <algorithm>
#include <string>

#include "core/support/error.h"
#include "render/gl/draw_options.h"
#include "render/gl/gl_context.h"
#include "shaders/embedded_shaders.h"

namespace gps {

VertexDots::VertexDots()
    : program_("vertex dots", {{GL_VERTEX_SHADER, {shaders::dots_vert}}, {GL_FRAGMENT_SHADER, {shaders::dots_frag}}}) {
  glVertexArrayVertexBuffer(vao_, 0, positions_, 0, 3 * sizeof(float));
  glEnableVertexArrayAttrib(vao_, 0);
  glVertexArrayAttribFormat(vao_, 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao_, 0, 0);
  check_gl_errors("creating the vertex dots");
}

void VertexDots::set_vertices(const CovarianceMesh& mesh, const std::vector<int>& vertices,
                              const NormalisedFrame& frame) {
  for (const int v : vertices)
    if (v < 0 || size_t(v) >= mesh.n_vertices())
      throw Error("the dots name vertex " + std::to_string(v) + " of a mesh of " + std::to_string(mesh.n_vertices()) +
                  " vertices");
  std::vector<float> placed(3 * vertices.size());
  const long long n = (long long)vertices.size();
#pragma omp parallel for schedule(static) if (n >= 65536)
  for (long long i = 0; i < n; ++i) {
    const Vec3& m = mesh.mean(size_t(vertices[size_t(i)]));
    const glm::dvec3 p = frame.to_frame(glm::dvec3(m.x(), m.y(), m.z()));
    for (int k = 0; k < 3; ++k) placed[3 * size_t(i) + size_t(k)] = float(p[k]);
  }
  frame_ = frame;
  count_ = vertices.size();
  if (placed == placed_) return;
  if (placed.size() > capacity_) {  // room to grow, so that a selection growing a little does not reallocate
    capacity_ = std::max<size_t>(placed.size() + placed.size() / 4, 3);
    glNamedBufferData(positions_, GLsizeiptr(capacity_ * sizeof(float)), nullptr, GL_DYNAMIC_DRAW);
  }
  if (!placed.empty()) glNamedBufferSubData(positions_, 0, GLsizeiptr(placed.size() * sizeof(float)), placed.data());
  placed_ = std::move(placed);
  check_gl_errors("uploading the vertex dots");
}

void VertexDots::draw(int width, int height, const Camera& camera, const Style& style) const {
  if (count_ == 0 || width <= 0 || height <= 0) return;
  program_.set("u_view_projection", frame_view_projection(camera, float(width) / float(height), frame_));
  program_.set("u_diameter", style.diameter);
  program_.set("u_colour", style.colour);
  program_.use();
  glViewport(0, 0, width, height);
  glBindVertexArray(vao_);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_PROGRAM_POINT_SIZE);
  glDrawArrays(GL_POINTS, 0, GLsizei(count_));
  glDisable(GL_PROGRAM_POINT_SIZE);
  glDisable(GL_BLEND);
  glBindVertexArray(0);
  check_gl_errors("drawing the vertex dots");
}

void VertexDots::draw(const RenderTarget& target, const Camera& camera, const Style& style) const {
  target.bind();
  target.set_colour_only(true);
  draw(target.width(), target.height(), camera, style);
  target.set_colour_only(false);
}

}  // namespace gps
