// Triangles the surface cache stored (render/surface_cache.h): the tessellation evaluation
// outputs as transform feedback wrote them, projected as patch_tese.glsl projects them. No geometry
// stage follows (it cost 1.5-2x the frame on llvmpipe), so llvmpipe rounds the viewport transform
// apart from the live pipeline: the AOVs agree to ~1e-4, not bit for bit (test_surface_cache.cpp).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_grid;
layout(location = 3) in int a_kind;
uniform mat4 u_view_projection;
out vec3 v_position;
out vec3 v_normal;
out vec3 v_grid;
flat out int v_kind;

void main() {
  v_position = a_position;
  v_normal = a_normal;
  v_grid = a_grid;
  v_kind = a_kind;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
