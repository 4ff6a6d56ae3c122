// What the quad and triangle evaluation stages share (patch_tese.glsl, triangle_tese.glsl; put in
// place of their #include by cmake/embed_shaders.cmake): the outputs and main(). A vertex on the
// patch's boundary is evaluated from the canonical patch of that point (canonical_edge.glsl), so
// that every patch beside an edge or around a corner generates it bit for bit alike; then the GPS
// limit point, its analytic normal (thesis Eq. 3.12) and the clip position; on an infinitely sharp
// crease the normal of the patch's own side (limit_point.glsl). The including stage defines
// kCorners, boundary_point(), tess_uv() (the tessellation coordinate as patch parameters),
// evaluate_limit() and grid_coordinates().
uniform mat4 u_view_projection;
#include "shaders/limit_point.glsl"

out vec3 v_position;
out vec3 v_normal;
out vec3 v_patch_uv;  // patch id and (u, v), for transform feedback checks
out vec3 v_evaluated; // the patch id and (u, v) evaluated: the canonical patch on patch edges (canonical_edge.glsl),
                      // on an infinitely sharp crease the edge point (limit_point.glsl, own_crease_normal)
out vec3 v_grid;      // tessellation grid coordinates, for the wireframe (grid_coordinates())
flat out int v_kind;  // plan node kind (gpu_layout.h)
// v_normal · 2^v_kind: normal and kind in one vector for the surface cache (cache_vert.glsl takes
// them apart exactly, a power of two scaling no bit of the normal away).
out vec3 v_stored_normal;

void main() {
  vec3 mu;
  vec2 uv = tess_uv();
  int patch_id = tc_patch;
  vec2 eval_uv = uv;
  EdgePoint e, c;
  int corner = -1;
  bool crease = false;
  if (boundary_point(e)) {
    uv = edge_point_uv(e, kCorners);
    c = canonical_boundary_point(e, kCorners);
    patch_id = c.patch_id;
    eval_uv = edge_point_uv(c, kCorners);
    if (c.i == 0) corner = c.edge;  // a corner: step 0 of its owner's edge that starts there
    crease = sharp_boundary_point(e, kCorners);
  }
  // One evaluation for every vertex of the batch, boundary or not; a second on a crease only.
  limit_point(patch_id, eval_uv, corner, mu, v_normal, v_kind);
  v_evaluated = vec3(float(patch_id), eval_uv);
  if (crease) own_crease_normal(e, c, v_normal, v_evaluated);
  v_position = mu;
  v_stored_normal = ldexp(v_normal, ivec3(v_kind));
  v_patch_uv = vec3(float(tc_patch), uv);
  v_grid = grid_coordinates();
  gl_Position = u_view_projection * vec4(mu, 1.0);
}
