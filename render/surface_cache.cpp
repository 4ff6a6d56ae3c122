#include "render/surface_cache.h"

#include <glad/gl.h>

#include <algorithm>
#include <cmath>

#include "render/gl_context.h"

namespace gps {

SurfaceCache::SurfaceCache() {
  glCreateBuffers(1, &buffer_);
  glCreateVertexArrays(1, &vao_);
  glCreateQueries(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, 1, &written_query_);
  glVertexArrayVertexBuffer(vao_, 0, buffer_, 0, kVertexBytes);
  for (GLuint a = 0; a < 3; ++a) {
    glEnableVertexArrayAttrib(vao_, a);
    glVertexArrayAttribFormat(vao_, a, 3, GL_FLOAT, GL_FALSE, a * 3 * sizeof(float));
    glVertexArrayAttribBinding(vao_, a, 0);
  }
  glEnableVertexArrayAttrib(vao_, 3);
  glVertexArrayAttribIFormat(vao_, 3, 1, GL_INT, 9 * sizeof(float));
  glVertexArrayAttribBinding(vao_, 3, 0);
  check_gl_errors("creating the surface cache");
}

SurfaceCache::~SurfaceCache() {
  glDeleteBuffers(1, &buffer_);
  glDeleteVertexArrays(1, &vao_);
  glDeleteQueries(1, &written_query_);
}

void SurfaceCache::set_cage(const CovarianceMesh& mesh) {
  cage_positions_.resize(mesh.n_vertices());
  for (size_t i = 0; i < mesh.n_vertices(); ++i) {
    const Vec3 m = mesh.mean(i);
    cage_positions_[i] = glm::vec3(float(m.x()), float(m.y()), float(m.z()));
  }
  cage_edges_.clear();
  cage_edges_.reserve(2 * mesh.mesh.n_edges());
  for (const auto e : mesh.mesh.edges()) cage_edges_.insert(cage_edges_.end(), {unsigned(e.v0().idx()), unsigned(e.v1().idx())});
  stored_ = false;
}

void SurfaceCache::update_cage(const CovarianceMesh& mesh, const std::vector<int>& changed) {
  for (const int v : changed) {
    const Vec3 m = mesh.mean(size_t(v));
    cage_positions_[size_t(v)] = glm::vec3(float(m.x()), float(m.y()), float(m.z()));
  }
  stored_ = false;
}

bool SurfaceCache::current(const Key& key, const glm::mat4& view_projection, glm::vec2 viewport) const {
  if (!stored_ || !(key == key_)) return false;
  return key.pixels <= 0.0f || camera_close(view_projection, viewport, key.pixels);
}

// The adaptive rule (see the header): every base edge's projected length, floored at `pixels`,
// within the hysteresis factor of its length under the captured camera; no edge end crossing the
// eye plane (the shaders give such edges level 64).
bool SurfaceCache::camera_close(const glm::mat4& view_projection, glm::vec2 viewport, float pixels) const {
  if (view_projection == view_projection_ && viewport == viewport_) return true;
  struct Projected {
    glm::vec2 xy;
    bool behind;
  };
  const auto project = [](const glm::mat4& m, glm::vec2 size, const glm::vec3& p) {
    const glm::vec4 c = m * glm::vec4(p, 1.0f);
    return Projected{glm::vec2(c) / c.w * 0.5f * size, c.w <= 0.0f};
  };
  const float low = 1.0f / hysteresis_, high = hysteresis_;
  for (size_t e = 0; e + 1 < cage_edges_.size(); e += 2) {
    const glm::vec3& a = cage_positions_[cage_edges_[e]];
    const glm::vec3& b = cage_positions_[cage_edges_[e + 1]];
    const Projected a0 = project(view_projection_, viewport_, a), b0 = project(view_projection_, viewport_, b);
    const Projected a1 = project(view_projection, viewport, a), b1 = project(view_projection, viewport, b);
    const bool behind0 = a0.behind || b0.behind, behind1 = a1.behind || b1.behind;
    if (behind0 != behind1) return false;
    if (behind0) continue;
    const float l0 = std::max(glm::length(a0.xy - b0.xy), pixels), l1 = std::max(glm::length(a1.xy - b1.xy), pixels);
    const float ratio = l1 / l0;
    if (!(ratio >= low && ratio <= high)) return false;
  }
  return true;
}

void SurfaceCache::reserve(long long triangles) {
  const long long most = std::max(1ll, limit_bytes_ / (3 * kVertexBytes));
  triangles = std::clamp(triangles, 1ll, most);
  // Grow to fit; shrink where the buffer is four times what is needed.
  if (triangles <= capacity_ && 4 * triangles >= capacity_) return;
  capacity_ = triangles;
  glNamedBufferData(buffer_, GLsizeiptr(capacity_ * 3 * kVertexBytes), nullptr, GL_DYNAMIC_COPY);
}

bool SurfaceCache::capture(const Key& key, const glm::mat4& view_projection, glm::vec2 viewport, long long estimate,
                           const std::function<void()>& draw_patches) {
  ++captures_;
  key_ = key;
  view_projection_ = view_projection;
  viewport_ = viewport;
  stored_ = true;
  refused_ = false;
  reserve(estimate);
  const long long most = limit_bytes_ / (3 * kVertexBytes);
  for (;;) {
    glBindBufferRange(GL_TRANSFORM_FEEDBACK_BUFFER, 0, buffer_, 0, GLsizeiptr(capacity_ * 3 * kVertexBytes));
    glEnable(GL_RASTERIZER_DISCARD);
    glBeginQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, written_query_);
    glBeginTransformFeedback(GL_TRIANGLES);
    draw_patches();
    glEndTransformFeedback();
    glEndQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
    glDisable(GL_RASTERIZER_DISCARD);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
    GLuint64 written = 0;
    glGetQueryObjectui64v(written_query_, GL_QUERY_RESULT, &written);
    check_gl_errors("capturing the surface");
    triangles_ = (long long)written;
    if (triangles_ < capacity_) return true;  // a full buffer may have dropped triangles
    if (capacity_ >= most) {
      refused_ = true;
      triangles_ = 0;
      return false;
    }
    reserve(std::min(2 * capacity_, most));
  }
}

void SurfaceCache::draw() const {
  glBindVertexArray(vao_);
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(3 * triangles_));
}

}  // namespace gps
