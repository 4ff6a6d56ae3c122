// Evaluates the Loop GPS limit surface at the tessellation coordinate (loop_eval.glsl): patch
// parameters (u, v) are the barycentrics of corners 1 and 2.
layout(triangles, equal_spacing, ccw) in;
patch in int tc_patch;

const int kCorners = 3;

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

vec2 tess_uv() { return gl_TessCoord.yz; }

// Node kinds: box spline, extraordinary (exact).
void evaluate_limit(int patch_id, vec2 uv, out vec3 mu, out vec3 mu_u, out vec3 mu_v, out int kind) {
  evaluate_triangle_plan(patch_id, uv.x, uv.y, mu, mu_u, mu_v, kind);
}

// The tessellation grid: the three barycentrics times the inner level.
vec3 grid_coordinates() { return gl_TessCoord * gl_TessLevelInner[0]; }

#include "shaders/limit_point_tese.glsl"
