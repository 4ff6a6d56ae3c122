// Evaluates the GPS limit surface at the tessellation coordinate: plan descent, q, q_u, q_v in 9D,
// back to μ and the analytic normal (thesis Eq. 3.12).
layout(quads, equal_spacing, ccw) in;
patch in int tc_patch;

uniform mat4 u_view_projection;

out vec3 v_position;
out vec3 v_normal;
out vec3 v_patch_uv;  // patch id and (u, v), for transform feedback checks
out vec3 v_grid;      // tessellation grid coordinates, for the wireframe (z: no third family)
flat out int v_kind;  // plan node kind: 1 regular (exact B-spline), 2 terminal (Bézier approximation)

// The tessellator places the vertices of an outer edge of level n near i/n (llvmpipe: in fixed
// point), and the roundings differ between levels. A quad edge at level 2n meets two half-size
// patches at level n (core/plan_table.h, PatchEdgePart): snapped to the exact i/n, a vertex of the
// quad and the vertex of the half beside it evaluate the same limit point at the same parameter.
vec2 edge_snapped_coord() {
  vec2 uv = gl_TessCoord.xy;
  float n_u0 = ceil(gl_TessLevelOuter[0]), n_v0 = ceil(gl_TessLevelOuter[1]);
  float n_u1 = ceil(gl_TessLevelOuter[2]), n_v1 = ceil(gl_TessLevelOuter[3]);
  if (uv.y == 0.0) uv.x = round(uv.x * n_v0) / n_v0;
  else if (uv.y == 1.0) uv.x = round(uv.x * n_v1) / n_v1;
  if (uv.x == 0.0) uv.y = round(uv.y * n_u0) / n_u0;
  else if (uv.x == 1.0) uv.y = round(uv.y * n_u1) / n_u1;
  return uv;
}

void main() {
  vec3 mu, mu_u, mu_v;
  vec2 uv = edge_snapped_coord();
  evaluate_plan(tc_patch, uv, mu, mu_u, mu_v, v_kind);
  v_position = mu;
  v_normal = normalize(cross(mu_u, mu_v));
  v_patch_uv = vec3(float(tc_patch), uv);
  v_grid = vec3(gl_TessCoord.xy * vec2(gl_TessLevelInner[0], gl_TessLevelInner[1]), 0.5);
  gl_Position = u_view_projection * vec4(mu, 1.0);
}
