#include "render/overlays/ellipsoid_overlay.h"

#include <glad/gl.h>

#include <cmath>

#include "core/edit/covariance_edit.h"
#include "render/gl/gl_context.h"
#include "shaders/embedded_shaders.h"

namespace gps {

EllipsoidOverlay::EllipsoidOverlay()
    : program_("ellipsoids",
               {{GL_VERTEX_SHADER, {shaders::ellipsoid_vert}}, {GL_FRAGMENT_SHADER, {shaders::lines_frag}}}) {
  // Three unit circles (xy, yz, zx planes) as line segments, instanced per vertex.
  std::vector<float> circles;
  const int segments = 32;
  for (int plane = 0; plane < 3; ++plane)
    for (int i = 0; i < segments; ++i)
      for (const int j : {i, i + 1}) {
        const float a = 6.2831853f * float(j) / segments;
        float p[3] = {0, 0, 0};
        p[plane] = std::cos(a);
        p[(plane + 1) % 3] = std::sin(a);
        circles.insert(circles.end(), p, p + 3);
      }
  circle_vertex_count_ = int(circles.size() / 3);
  glNamedBufferData(circle_vbo_, GLsizeiptr(circles.size() * sizeof(float)), circles.data(), GL_STATIC_DRAW);
  glVertexArrayVertexBuffer(vao_, 0, circle_vbo_, 0, 3 * sizeof(float));
  glEnableVertexArrayAttrib(vao_, 0);
  glVertexArrayAttribFormat(vao_, 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao_, 0, 0);
  for (GLuint c = 0; c < 4; ++c) {
    glEnableVertexArrayAttrib(vao_, 1 + c);
    glVertexArrayAttribFormat(vao_, 1 + c, 4, GL_FLOAT, GL_FALSE, c * 4 * sizeof(float));
    glVertexArrayAttribBinding(vao_, 1 + c, 1);
  }
  glVertexArrayBindingDivisor(vao_, 1, 1);
  check_gl_errors("creating the ellipsoid overlay");
}

void EllipsoidOverlay::upload(const FramedGaussians& gaussians, const std::vector<int>* changed) {
  // Σ = V diag(σ²) Vᵀ; the unit sphere maps to the 1-σ ellipsoid by [V diag(σ) | μ] (column-major mat4).
  const auto transform = [&gaussians](size_t i, float* m) {
    const EllipsoidAxes e = ellipsoid_axes(gaussians.covariance(i));
    const Mat3 root = e.axes * e.sigmas.asDiagonal();
    for (int c = 0; c < 3; ++c) {
      for (int r = 0; r < 3; ++r) m[4 * c + r] = float(root(r, c));
      m[4 * c + 3] = 0.0f;
    }
    const Vec3 mu = gaussians.mean(i);
    m[12] = float(mu.x()), m[13] = float(mu.y()), m[14] = float(mu.z()), m[15] = 1.0f;
  };
  if (changed) {  // an edit: only the changed vertices' instances
    for (const int v : *changed) {
      float m[16];
      transform(size_t(v), m);
      glNamedBufferSubData(instance_vbo_, GLintptr(sizeof m * size_t(v)), sizeof m, m);
    }
    return;
  }
  std::vector<float> all(std::max<size_t>(1, gaussians.n_vertices()) * 16, 0.0f);
  for (size_t i = 0; i < gaussians.n_vertices(); ++i) transform(i, &all[16 * i]);
  glNamedBufferData(instance_vbo_, GLsizeiptr(all.size() * sizeof(float)), all.data(), GL_DYNAMIC_DRAW);
  glVertexArrayVertexBuffer(vao_, 1, instance_vbo_, 0, 16 * sizeof(float));
  count_ = int(gaussians.n_vertices());
}

void EllipsoidOverlay::draw(const glm::mat4& view_projection, float sigma, const std::vector<int>* only) {
  program_.set("u_view_projection", view_projection);
  program_.set("u_sigma", sigma);
  program_.set("u_color", glm::vec4(0.15f, 0.35f, 0.85f, 1.0f));
  program_.use();
  glBindVertexArray(vao_);
  if (!only) {
    glDrawArraysInstanced(GL_LINES, 0, circle_vertex_count_, count_);
    return;
  }
  // The circles once per instance of each run of consecutive vertices (baseInstance: the run's first).
  struct Command {
    GLuint count, instances, first, base_instance;
  };
  std::vector<Command> commands;
  for (const int v : *only) {
    if (v < 0 || v >= count_) continue;
    if (!commands.empty() && commands.back().base_instance + commands.back().instances == GLuint(v))
      ++commands.back().instances;
    else
      commands.push_back({GLuint(circle_vertex_count_), 1, 0, GLuint(v)});
  }
  if (commands.empty()) return;
  glNamedBufferData(indirect_, GLsizeiptr(commands.size() * sizeof(Command)), commands.data(), GL_STREAM_DRAW);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, indirect_);
  glMultiDrawArraysIndirect(GL_LINES, nullptr, GLsizei(commands.size()), 0);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
}

}  // namespace gps
