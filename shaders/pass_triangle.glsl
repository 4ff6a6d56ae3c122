// Passes each triangle through a geometry stage with its vertices' outputs unchanged but for v_grid,
// which the including stage (cache_geom.glsl, mesh_geom.glsl; put in place of their #include by
// cmake/embed_shaders.cmake) gives as triangle_grid(i) for corner i.
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

vec3 triangle_grid(int i);

void main() {
  for (int i = 0; i < 3; ++i) {
    v_position = g_position[i];
    v_normal = g_normal[i];
    v_grid = triangle_grid(i);
    v_kind = g_kind[i];
    gl_Position = gl_in[i].gl_Position;
    EmitVertex();
  }
  EndPrimitive();
}
