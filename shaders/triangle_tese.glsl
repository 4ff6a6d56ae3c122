// Evaluates the Loop GPS limit surface at the tessellation coordinate (loop_eval.glsl): patch
// parameters (u, v) are the barycentrics of corners 1 and 2.
layout(triangles, equal_spacing, ccw) in;
patch in int tc_patch;

uniform mat4 u_view_projection;

out vec3 v_position;
out vec3 v_normal;
out vec3 v_patch_uv;  // patch id and (u, v), for transform feedback checks
out vec3 v_grid;      // tessellation grid: the three barycentrics times the inner level
flat out int v_kind;  // plan node kind: 1 box spline, 3 extraordinary (exact)

void main() {
  vec3 mu, mu_u, mu_v;
  evaluate_triangle_plan(tc_patch, gl_TessCoord.y, gl_TessCoord.z, mu, mu_u, mu_v, v_kind);
  v_position = mu;
  v_normal = normalize(cross(mu_u, mu_v));
  v_patch_uv = vec3(float(tc_patch), gl_TessCoord.yz);
  v_grid = gl_TessCoord * gl_TessLevelInner[0];
  gl_Position = u_view_projection * vec4(mu, 1.0);
}
