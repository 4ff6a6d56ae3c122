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

void main() {
  vec3 mu, mu_u, mu_v;
  evaluate_plan(tc_patch, gl_TessCoord.xy, mu, mu_u, mu_v, v_kind);
  v_position = mu;
  v_normal = normalize(cross(mu_u, mu_v));
  v_patch_uv = vec3(float(tc_patch), gl_TessCoord.xy);
  v_grid = vec3(gl_TessCoord.xy * vec2(gl_TessLevelInner[0], gl_TessLevelInner[1]), 0.5);
  gl_Position = u_view_projection * vec4(mu, 1.0);
}
