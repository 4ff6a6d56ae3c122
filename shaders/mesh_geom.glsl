// Wireframe over triangles from a buffer (reference subdivision, CPU tessellation, the surface
// cache): each triangle passes through with its corners' barycentric coordinates in v_grid; the
// fragment shader draws a line where one of the three is zero.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in vec3 g_position[];
in vec3 g_normal[];
in vec3 g_grid[];
flat in int g_kind[];
out vec3 v_position;
out vec3 v_normal;
out vec3 v_grid;
flat out int v_kind;

void main() {
  const vec3 corner[3] = vec3[3](vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, 1.0));
  for (int i = 0; i < 3; ++i) {
    v_position = g_position[i];
    v_normal = g_normal[i];
    v_grid = corner[i];
    v_kind = g_kind[i];
    gl_Position = gl_in[i].gl_Position;
    EmitVertex();
  }
  EndPrimitive();
}
