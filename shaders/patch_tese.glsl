// Evaluates the GPS limit surface at the tessellation coordinate: plan descent, q, q_u, q_v in 9D,
// back to μ and the analytic normal (thesis Eq. 3.12).
layout(quads, equal_spacing, ccw) in;
patch in int tc_patch;

const int kCorners = 4;

// The tessellator places the vertices of an outer edge of level n near i/n (llvmpipe: in fixed
// point). A vertex on the patch's boundary is named by its edge and step i (integers), and
// evaluated from the canonical patch of that point at exactly i/n (canonical_edge.glsl): every
// patch beside an edge or around a corner, T-junctions with half-size patches included
// (core/plans/patch_plans.h, PatchEdgePart), generates it bit for bit alike.
bool boundary_point(out EdgePoint e) {
  vec2 t = gl_TessCoord.xy;
  int n0 = int(ceil(gl_TessLevelOuter[1])), n1 = int(ceil(gl_TessLevelOuter[2]));  // edges v = 0, u = 1
  int n2 = int(ceil(gl_TessLevelOuter[3])), n3 = int(ceil(gl_TessLevelOuter[0]));  // edges v = 1, u = 0
  if (t.y == 0.0) e = EdgePoint(tc_patch, 0, int(round(t.x * float(n0))), n0);
  else if (t.x == 1.0) e = EdgePoint(tc_patch, 1, int(round(t.y * float(n1))), n1);
  else if (t.y == 1.0) e = EdgePoint(tc_patch, 2, n2 - int(round(t.x * float(n2))), n2);
  else if (t.x == 0.0) e = EdgePoint(tc_patch, 3, n3 - int(round(t.y * float(n3))), n3);
  else return false;
  return true;
}

vec2 tess_uv() { return gl_TessCoord.xy; }

// Node kinds: regular (exact B-spline), terminal (Bézier approximation), extraordinary (exact).
void evaluate_limit(int patch_id, vec2 uv, out vec3 mu, out vec3 mu_u, out vec3 mu_v, out int kind) {
  evaluate_plan(patch_id, uv, mu, mu_u, mu_v, kind);
}

// The tessellation grid's two families (z: no third).
vec3 grid_coordinates() { return vec3(gl_TessCoord.xy * vec2(gl_TessLevelInner[0], gl_TessLevelInner[1]), 0.5); }

#include "shaders/limit_point_tese.glsl"
