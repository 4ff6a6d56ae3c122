// Wireframe over static triangles (reference subdivision, CPU tessellation): each triangle passes
// through with its corners' barycentric coordinates in v_grid; the fragment shader draws a line where
// one of the three is zero.
#include "shaders/pass_triangle.glsl"

vec3 triangle_grid(int i) {
  const vec3 corner[3] = vec3[3](vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, 1.0));
  return corner[i];
}
