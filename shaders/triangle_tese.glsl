// Evaluates the Loop GPS limit surface at the tessellation coordinate (loop_eval.glsl): patch
// parameters (u, v) are the barycentrics of corners 1 and 2.
layout(triangles, equal_spacing, ccw) in;
patch in int tc_patch;

uniform mat4 u_view_projection;

out vec3 v_position;
out vec3 v_normal;
out vec3 v_patch_uv;  // patch id and (u, v), for transform feedback checks
out vec3 v_evaluated; // the patch id and (u, v) evaluated: the canonical patch on patch edges (canonical_edge.glsl)
out vec3 v_grid;      // tessellation grid: the three barycentrics times the inner level
flat out int v_kind;  // plan node kind: 1 box spline, 3 extraordinary (exact)

// A vertex on the patch's boundary: its edge (k from corner k to k+1) and step i of the edge's
// level, evaluated from the canonical patch of that point (canonical_edge.glsl) so that the
// triangles beside an edge or around a corner generate it bit for bit alike.
bool boundary_point(out EdgePoint e) {
  vec3 t = gl_TessCoord;
  int n0 = int(ceil(gl_TessLevelOuter[2])), n1 = int(ceil(gl_TessLevelOuter[0])), n2 = int(ceil(gl_TessLevelOuter[1]));
  if (t.z == 0.0) e = EdgePoint(tc_patch, 0, int(round(t.y * float(n0))), n0);
  else if (t.x == 0.0) e = EdgePoint(tc_patch, 1, int(round(t.z * float(n1))), n1);
  else if (t.y == 0.0) e = EdgePoint(tc_patch, 2, int(round(t.x * float(n2))), n2);
  else return false;
  return true;
}

// Patch parameters (u, v) (barycentrics of corners 1 and 2) of an edge point.
vec2 edge_point_uv(EdgePoint e) {
  vec2 f = edge_fractions(e);
  if (e.edge == 0) return vec2(f.x, 0.0);
  // Edge 1 (u + v = 1): the larger parameter is 1 − the smaller, exactly (Sterbenz), so that
  // 1 − u − v is 0 and the exact extraordinary evaluation does not step outside the triangle.
  if (e.edge == 1) return 2 * e.i >= e.n ? vec2(1.0 - f.x, f.x) : vec2(f.y, 1.0 - f.y);
  return vec2(0.0, f.y);
}

void main() {
  vec3 mu, mu_u, mu_v;
  vec2 uv = gl_TessCoord.yz;
  int patch_id = tc_patch;
  vec2 eval_uv = uv;
  EdgePoint e;
  if (boundary_point(e)) {
    uv = edge_point_uv(e);
    EdgePoint c = canonical_boundary_point(e, 3);
    patch_id = c.patch_id;
    eval_uv = edge_point_uv(c);
  }
  evaluate_triangle_plan(patch_id, eval_uv.x, eval_uv.y, mu, mu_u, mu_v, v_kind);
  v_position = mu;
  v_normal = normalize(cross(mu_u, mu_v));
  v_patch_uv = vec3(float(tc_patch), uv);
  v_evaluated = vec3(float(patch_id), eval_uv);
  v_grid = gl_TessCoord * gl_TessLevelInner[0];
  gl_Position = u_view_projection * vec4(mu, 1.0);
}
