#include "render/pipeline/static_triangles.h"

#include <glad/gl.h>

#include <algorithm>

#include "render/gl/gl_context.h"
#include "shaders/embedded_shaders.h"

namespace gps {

StaticTriangles::StaticTriangles()
    : shaded_("mesh", {{GL_VERTEX_SHADER, {shaders::mesh_vert}}, {GL_FRAGMENT_SHADER, {shaders::shade_frag}}}),
      wire_("mesh_wire", {{GL_VERTEX_SHADER, {shaders::geometry_next, shaders::mesh_vert}},
                          {GL_GEOMETRY_SHADER, {shaders::mesh_geom}},
                          {GL_FRAGMENT_SHADER, {shaders::shade_frag}}}) {}

void StaticTriangles::set(const TriangleMesh& t) {
  std::vector<float> vertices;
  vertices.reserve(t.positions.size() * 6);
  for (size_t i = 0; i < t.positions.size(); ++i)
    for (const Vec3* v : {&t.positions[i], &t.normals[i]})
      for (int k = 0; k < 3; ++k) vertices.push_back(float((*v)[k]));
  std::vector<unsigned> indices;
  for (const auto& tri : t.triangles)
    indices.insert(indices.end(), {unsigned(tri[0]), unsigned(tri[1]), unsigned(tri[2])});
  count_ = int(t.triangles.size());
  glNamedBufferData(vbo_, GLsizeiptr(std::max<size_t>(1, vertices.size()) * sizeof(float)), vertices.data(),
                    GL_STATIC_DRAW);
  glNamedBufferData(ibo_, GLsizeiptr(std::max<size_t>(1, indices.size()) * sizeof(unsigned)), indices.data(),
                    GL_STATIC_DRAW);
  glVertexArrayVertexBuffer(vao_, 0, vbo_, 0, 6 * sizeof(float));
  glVertexArrayElementBuffer(vao_, ibo_);
  for (GLuint a = 0; a < 2; ++a) {
    glEnableVertexArrayAttrib(vao_, a);
    glVertexArrayAttribFormat(vao_, a, 3, GL_FLOAT, GL_FALSE, a * 3 * sizeof(float));
    glVertexArrayAttribBinding(vao_, a, 0);
  }
  check_gl_errors("uploading triangles");
}

void StaticTriangles::draw() const {
  glBindVertexArray(vao_);
  glDrawElements(GL_TRIANGLES, 3 * count_, GL_UNSIGNED_INT, nullptr);
}

}  // namespace gps
