#pragma once
// Triangles from a vertex buffer (CPU tessellation, reference subdivision) with the surface's
// shading: the static-buffer floor the benchmark measures the patch pipeline against.
#include "core/evaluation/triangle_mesh.h"
#include "render/gl/gl_object.h"
#include "render/gl/shader_program.h"

namespace gps {

class StaticTriangles {
public:
  /// Needs a current GL 4.5 context.
  StaticTriangles();
  StaticTriangles(const StaticTriangles&) = delete;
  StaticTriangles& operator=(const StaticTriangles&) = delete;

  void set(const TriangleMesh& triangles);
  /// The program to draw with (set its frame uniforms, then draw()).
  const ShaderProgram& program(bool wireframe) const { return wireframe ? wire_ : shaded_; }
  void draw() const;
  /// Whether set() gave it triangles.
  bool drawn() const { return count_ > 0; }

private:
  ShaderProgram shaded_, wire_;
  GlVertexArray vao_;
  GlBuffer vbo_, ibo_;
  int count_ = 0;
};

}  // namespace gps
