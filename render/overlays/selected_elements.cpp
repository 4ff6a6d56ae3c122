#include "render/overlays/selected_elements.h"

#include <glad/gl.h>

#include <algorithm>
#include <string>

#include "core/support/error.h"
#include "render/gl/draw_options.h"
#include "render/gl/gl_context.h"
#include "shaders/embedded_shaders.h"

namespace gps {

namespace {
constexpr int kAlways = -2, kNone = -1;  // an item's facing faces: a boundary edge shows always
}  // namespace

SelectedElements::TexelBuffer::TexelBuffer(unsigned format_) : format(format_), texture(GL_TEXTURE_BUFFER) {
  upload(nullptr, 16);  // a texture buffer needs a store to be bound
}

void SelectedElements::TexelBuffer::upload(const void* data, size_t bytes) {
  if (bytes > capacity) {  // room to grow, so that a selection growing a little does not reallocate
    capacity = std::max<size_t>(bytes + bytes / 4, 16);
    glNamedBufferData(buffer, GLsizeiptr(capacity), nullptr, GL_DYNAMIC_DRAW);
    glTextureBuffer(texture, format, buffer);
  }
  if (data && bytes > 0) glNamedBufferSubData(buffer, 0, GLsizeiptr(bytes), data);
}

SelectedElements::SelectedElements()
    : fill_("selected faces",
            {{GL_VERTEX_SHADER, {shaders::selected_vert}}, {GL_FRAGMENT_SHADER, {shaders::selected_fill_frag}}}),
      lines_("selected lines", {{GL_VERTEX_SHADER, {shaders::selected_vert}},
                                {GL_GEOMETRY_SHADER, {shaders::selected_lines_geom}},
                                {GL_FRAGMENT_SHADER, {shaders::selected_lines_frag}}}),
      positions_(GL_RGBA32F),
      planes_(GL_RGBA32F),
      items_(GL_RGBA32I) {
  check_gl_errors("creating the selection highlight");
}

void SelectedElements::set_elements(const CovarianceMesh& mesh, const std::vector<std::array<int, 2>>& edges,
                                    const std::vector<int>& faces, const NormalisedFrame& frame) {
  for (const int f : faces)
    if (f < 0 || size_t(f) >= mesh.n_faces())
      throw Error("the highlight names face " + std::to_string(f) + " of a mesh of " + std::to_string(mesh.n_faces()) +
                  " faces");
  for (const auto& ends : edges)
    for (const int v : ends)
      if (v < 0 || size_t(v) >= mesh.n_vertices())
        throw Error("the highlight names vertex " + std::to_string(v) + " of a mesh of " +
                    std::to_string(mesh.n_vertices()) + " vertices");
  if (mesh.shape() != shape_ || edges != edges_ || faces != faces_) {
    // The items: each face's fan and outline, then the edges; the vertices and faces they read, numbered
    // in the order first read.
    std::vector<int> vertex_slot(mesh.n_vertices(), -1), face_slot(mesh.n_faces(), -1);
    std::vector<int> vertices, planed;
    const auto vertex = [&](int v) {
      if (vertex_slot[size_t(v)] < 0) vertex_slot[size_t(v)] = int(vertices.size()), vertices.push_back(v);
      return vertex_slot[size_t(v)];
    };
    const auto face = [&](int f) {
      if (f < 0) return kNone;
      if (face_slot[size_t(f)] < 0) {
        face_slot[size_t(f)] = int(planed.size()), planed.push_back(f);
        for (const int corner : mesh.face(size_t(f))) vertex(corner);
      }
      return face_slot[size_t(f)];
    };
    std::vector<int> triangles, outlines, lines;  // four ints per item
    for (const int f : faces) {
      const int slot = face(f);
      const std::span<const int> c = mesh.face(size_t(f));
      for (size_t k = 1; k + 1 < c.size(); ++k)
        triangles.insert(triangles.end(),
                         {vertex_slot[size_t(c[0])], vertex_slot[size_t(c[k])], vertex_slot[size_t(c[k + 1])], slot});
      for (size_t k = 0; k < c.size(); ++k)
        outlines.insert(outlines.end(),
                        {vertex_slot[size_t(c[k])], vertex_slot[size_t(c[(k + 1) % c.size()])], slot, slot});
    }
    const std::vector<int>& sides = mesh.connectivity().edge_faces;
    for (const auto& [a, b] : edges) {
      const int e = mesh.find_edge(a, b);
      if (e < 0) continue;
      const int f0 = sides[2 * size_t(e)], f1 = sides[2 * size_t(e) + 1];
      const int s0 = f1 < 0 ? kAlways : face(f0), s1 = f1 < 0 ? kNone : face(f1);
      lines.insert(lines.end(), {vertex(a), vertex(b), s0, s1});
    }
    triangles_ = triangles.size() / 4, outline_lines_ = outlines.size() / 4, edge_lines_ = lines.size() / 4;
    triangles.insert(triangles.end(), outlines.begin(), outlines.end());
    triangles.insert(triangles.end(), lines.begin(), lines.end());
    items_.upload(triangles.data(), triangles.size() * sizeof(int));
    shape_ = mesh.shape(), edges_ = edges, faces_ = faces;
    vertices_ = std::move(vertices);
    plane_offsets_.assign(1, 0), plane_corners_.clear();
    for (const int f : planed) {
      for (const int corner : mesh.face(size_t(f))) plane_corners_.push_back(vertex_slot[size_t(corner)]);
      plane_offsets_.push_back(int(plane_corners_.size()));
    }
    placed_.clear();  // placed again below
  }
  // The vertices' places in the frame, then each face's plane there (its normal by Newell's formula,
  // through its centroid), computed in double.
  const long long n_vertices = (long long)vertices_.size(), n_faces = (long long)plane_offsets_.size() - 1;
  std::vector<float> placed(4 * size_t(n_vertices + n_faces));
  std::vector<glm::dvec3> framed(vertices_.size());
#pragma omp parallel for schedule(static) if (n_vertices >= 65536)
  for (long long ii = 0; ii < n_vertices; ++ii) {
    const size_t i = size_t(ii);
    const Vec3& m = mesh.mean(size_t(vertices_[i]));
    framed[i] = frame.to_frame(glm::dvec3(m.x(), m.y(), m.z()));
    for (int k = 0; k < 3; ++k) placed[4 * i + size_t(k)] = float(framed[i][k]);
    placed[4 * i + 3] = 1.0f;
  }
#pragma omp parallel for schedule(static) if (n_faces >= 65536)
  for (long long jj = 0; jj < n_faces; ++jj) {
    const size_t j = size_t(jj);
    const std::span<const int> c(plane_corners_.data() + plane_offsets_[j],
                                 plane_corners_.data() + plane_offsets_[j + 1]);
    glm::dvec3 normal(0.0), centroid(0.0);
    for (size_t k = 0; k < c.size(); ++k) {
      const glm::dvec3& p = framed[size_t(c[k])];
      const glm::dvec3& q = framed[size_t(c[(k + 1) % c.size()])];
      normal += glm::cross(p, q);
      centroid += p;
    }
    centroid /= double(c.size());
    const double length = glm::length(normal);
    if (length > 0.0) normal /= length;
    float* plane = placed.data() + 4 * (vertices_.size() + j);
    for (int k = 0; k < 3; ++k) plane[k] = float(normal[k]);
    plane[3] = float(-glm::dot(normal, centroid));
  }
  frame_ = frame;
  if (placed == placed_) return;
  positions_.upload(placed.data(), 4 * vertices_.size() * sizeof(float));
  planes_.upload(placed.data() + 4 * vertices_.size(), 4 * size_t(n_faces) * sizeof(float));
  placed_ = std::move(placed);
  check_gl_errors("uploading the selection highlight");
}

void SelectedElements::draw(int width, int height, const Camera& camera, const Style& style) const {
  if (triangles_ + outline_lines_ + edge_lines_ == 0 || width <= 0 || height <= 0) return;
  const glm::mat4 view_projection = frame_view_projection(camera, float(width) / float(height), frame_);
  // The eye in the frame; a parallel view's direction towards it (a point at infinity).
  const glm::dvec3 eye = frame_.to_frame(camera.eye_double());
  const glm::vec4 eye_in_frame = camera.orthographic
                                     ? glm::vec4(glm::normalize(eye - frame_.to_frame(camera.target)), 0.0f)
                                     : glm::vec4(glm::vec3(eye), 1.0f);
  for (const ShaderProgram* program : {&fill_, &lines_}) {
    program->set("u_positions", 0);
    program->set("u_planes", 1);
    program->set("u_items", 2);
    program->set("u_view_projection", view_projection);
    program->set("u_eye", eye_in_frame);
  }
  lines_.set("u_viewport", glm::vec2(float(width), float(height)));
  glViewport(0, 0, width, height);
  glBindTextureUnit(0, positions_.texture);
  glBindTextureUnit(1, planes_.texture);
  glBindTextureUnit(2, items_.texture);
  glBindVertexArray(vao_);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  if (triangles_ > 0) {
    fill_.set("u_corners", 3);
    fill_.set("u_color", style.face_fill);
    fill_.use();
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(3 * triangles_));
  }
  lines_.set("u_corners", 2);
  const auto draw_lines = [&](size_t first, size_t count, const glm::vec4& colour, float width_pixels) {
    if (count == 0) return;
    lines_.set("u_color", colour);
    lines_.set("u_width", width_pixels);
    lines_.use();
    glDrawArrays(GL_LINES, GLint(2 * first), GLsizei(2 * count));
  };
  draw_lines(triangles_, outline_lines_, style.face_outline, style.outline_width);
  draw_lines(triangles_ + outline_lines_, edge_lines_, style.edge, style.edge_width);
  glDisable(GL_BLEND);
  glBindVertexArray(0);
  check_gl_errors("drawing the selection highlight");
}

void SelectedElements::draw(const RenderTarget& target, const Camera& camera, const Style& style) const {
  target.bind();
  target.set_colour_only(true);
  draw(target.width(), target.height(), camera, style);
  target.set_colour_only(false);
}

}  // namespace gps
