// Passes the cached triangles through unchanged. On llvmpipe a vertex shader without a later
// stage projects to the viewport in its own code, which rounds differently from the projection
// after tessellation or geometry stages (~1e-6 in the interpolated AOVs); with this stage the
// cached frame equals the live one bit for bit.
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
  for (int i = 0; i < 3; ++i) {
    v_position = g_position[i];
    v_normal = g_normal[i];
    v_grid = g_grid[i];
    v_kind = g_kind[i];
    gl_Position = gl_in[i].gl_Position;
    EmitVertex();
  }
  EndPrimitive();
}
