// Triangles from a vertex buffer (CPU tessellation or reference subdivision), shaded like the patches.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
uniform mat4 u_view_projection;
out vec3 v_position;
out vec3 v_normal;
out vec3 v_grid;      // no tessellation grid here
flat out int v_kind;  // no plan node either

void main() {
  v_position = a_position;
  v_normal = a_normal;
  v_grid = vec3(0.5);
  v_kind = 0;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
