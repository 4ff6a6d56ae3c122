// Triangles the surface cache stored (render/cache/surface_cache.h): the tessellation evaluation
// outputs as transform feedback wrote them, projected as patch_tese.glsl projects them. No geometry
// stage follows (one is costly on llvmpipe), so llvmpipe rounds the viewport transform apart from
// the live pipeline: the AOVs agree to ~1e-4, not bit for bit (tests/render/test_surface_cache.cpp).
// The stored normal is the normal times 2^kind (limit_point_tese.glsl): two attributes to fetch, as
// the static floor's, and the tessellation grid a third one only for the wireframe (CACHE_GRID:
// every attribute fetched adds to a cached frame's cost, on a GPU too).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_stored_normal;
#ifdef CACHE_GRID
layout(location = 2) in vec3 a_grid;
#endif
uniform mat4 u_view_projection;
out vec3 v_position;
out vec3 v_normal;
out vec3 v_grid;
flat out int v_kind;

void main() {
  v_position = a_position;
  // The largest component of a unit normal lies in [1/√3, 1], times 1.8 in [1.04, 1.8]: within one
  // binade, so that of the stored normal's largest component · 1.8 is the kind (its exponent bits;
  // no log2, length or round per vertex, which cost llvmpipe's vertex stage).
  vec3 magnitude = abs(a_stored_normal);
  v_kind = (floatBitsToInt(1.8 * max(magnitude.x, max(magnitude.y, magnitude.z))) >> 23) - 127;
  v_normal = ldexp(a_stored_normal, ivec3(-v_kind));  // exact, as the scaling was
#ifdef CACHE_GRID
  v_grid = a_grid;
#else
  v_grid = vec3(0.5);  // no tessellation wireframe
#endif
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
