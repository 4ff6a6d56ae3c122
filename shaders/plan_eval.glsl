// The plans and their points (core/plans/patch_plans.h) and their evaluation; mirrors core/evaluation/patch_eval.cpp,
// the descent and the extraordinary rows are one source for both (core/plans/plan_descent.h).
// Sums of points are 9D points about an anchor near the node (plan_point.glsl): q = (qa qb qc), three
// vec4 (xx xy xz yy) (yz zz y0 y1) (y2 0 0 0) with y = q̄ − q̂ · anchor; dvec4 with GPS_DOUBLE (gpu_layout.h).
layout(std430, binding = kBindingPoints) readonly buffer Points { point_vec4 points[]; };
#include "shaders/plan_point.glsl"
layout(std430, binding = kBindingNodes) readonly buffer Nodes { int nodes[]; };
layout(std430, binding = kBindingRoots) readonly buffer Roots { int roots[]; };
layout(std430, binding = kBindingCorners) readonly buffer CornerPoints { int corner_points[]; };
layout(std430, binding = kBindingPatchEdges) readonly buffer PatchEdges { int patch_edges[]; };  // quads: core/plans/patch_plans.h
layout(std430, binding = kBindingExtraordinaryTables) readonly buffer ExtraordinaryTables { float extraordinary_tables[]; };

#include "core/plans/plan_descent.h"

point_vec3 g_anchor = point_vec3(0.0);  // what the sums are taken about: set before an evaluation's first add_point

// The point of a leaf's net (n points from nodes[net]) weighing most in its sum at these weights,
// |w| tr q̂: the sums' anchor. About it the heaviest term is its own small offset y, not q̂ times a
// distance between anchors, which keeps too few digits in float where a needle's apex (q̂ ~ 1e5 I)
// is in the net. In a quad leaf at a boundary, phantom points included (core/patches/patch_basis.h).
// It costs one more pass over the net's weights per leaf.
#define GPS_HEAVIEST_POINT(n)                                  \
  int heaviest = nodes[net];                                   \
  float most = -1.0;                                           \
  for (int k = 0; k < n; ++k) {                                \
    int p = nodes[net + k];                                    \
    float weight = abs(w[k]) * abs(point_precision_trace(p));  \
    heaviest = weight > most ? p : heaviest;                   \
    most = max(most, weight);                                  \
  }                                                            \
  return heaviest;
int heaviest_point(int net, float w[16]) { GPS_HEAVIEST_POINT(16) }  // a quad leaf's net
int heaviest_point(int net, float w[12]) { GPS_HEAVIEST_POINT(12) }  // a box spline's

// μ and its tangents (thesis Eq. 3.12) from q, q_u, q_v about g_anchor (three vec4 each), in double,
// with μ_v made orthogonal to μ_u (their cross product, the normal, is the same): at an extraordinary
// node, as at a needle apex (q̂ ~ 1e5 I), the tangents can be nearly parallel, and the normal, their
// cross product in float, would lose its digits. From float sums at extraordinary nodes only (a GPU's
// doubles can be slow); from every leaf's sums where they are double themselves (GPS_DOUBLE).
void dual_to_surface_in_double(point_vec4 qa, point_vec4 qb, point_vec4 qc, point_vec4 ua, point_vec4 ub,
                               point_vec4 uc, point_vec4 va, point_vec4 vb, point_vec4 vc, float scale, out vec3 mu,
                               out vec3 mu_u, out vec3 mu_v) {
  dmat3 q_hat = dmat3(precision_of(qa, qb));
  dvec3 offset = precision_solve(q_hat, dvec3(offset_part(qb, qc)));
  mu = vec3(g_anchor + point_vec3(offset));  // about the anchor in the sums' own precision
  dvec3 tangent_u = precision_solve(q_hat, dvec3(offset_part(ub, uc)) - dmat3(precision_of(ua, ub)) * offset);
  dvec3 tangent_v = precision_solve(q_hat, dvec3(offset_part(vb, vc)) - dmat3(precision_of(va, vb)) * offset);
  tangent_v -= (dot(tangent_u, tangent_v) / dot(tangent_u, tangent_u)) * tangent_u;
  mu_u = scale * vec3(tangent_u);
  mu_v = scale * vec3(tangent_v);
}

// μ and its tangents (thesis Eq. 3.12) from q, q_u, q_v about g_anchor (three vec4 each), derivatives
// times `scale`: with y = q̄ − q̂ c, μ − c = [q̂]⁻¹ y and μ_u = [q̂]⁻¹ (y_u − [q̂_u] (μ − c)). In float,
// or in double where the sums are (GPS_DOUBLE).
void dual_to_surface(point_vec4 qa, point_vec4 qb, point_vec4 qc, point_vec4 ua, point_vec4 ub, point_vec4 uc,
                     point_vec4 va, point_vec4 vb, point_vec4 vc, float scale, out vec3 mu, out vec3 mu_u,
                     out vec3 mu_v) {
#ifdef GPS_DOUBLE
  dual_to_surface_in_double(qa, qb, qc, ua, ub, uc, va, vb, vc, scale, mu, mu_u, mu_v);
#else
  mat3 q_hat = precision_of(qa, qb);
  vec3 offset = precision_solve(q_hat, offset_part(qb, qc));
  mu = g_anchor + offset;
  mu_u = scale * precision_solve(q_hat, offset_part(ub, uc) - precision_of(ua, ub) * offset);
  mu_v = scale * precision_solve(q_hat, offset_part(vb, vc) - precision_of(va, vb) * offset);
#endif
}

// Plan point p with weight w and derivative weights w_u, w_v added to q = (qa qb qc) and its
// derivatives (ua ub uc), (va vb vc), three vec4 each (gpu_layout.h).
void add_point(int p, float w, float w_u, float w_v, inout point_vec4 qa, inout point_vec4 qb, inout point_vec4 qc,
               inout point_vec4 ua, inout point_vec4 ub, inout point_vec4 uc, inout point_vec4 va,
               inout point_vec4 vb, inout point_vec4 vc) {
  point_vec4 a, b, c;
  anchored_point(p, g_anchor, a, b, c);
  qa += w * a; qb += w * b; qc += w * c;
  ua += w_u * a; ub += w_u * b; uc += w_u * c;
  va += w_v * a; vb += w_v * b; vc += w_v * c;
}

// An extraordinary node (core/extraordinary/loop_extraordinary_tables.h,
// core/extraordinary/quad_extraordinary_tables.h) at (u, v) of its own domain: q and its u and v
// derivatives; mirrors evaluate_extraordinary in core/evaluation/patch_eval.cpp.
void evaluate_extraordinary_node(int node, bool quad, float u, float v, out point_vec4 qa, out point_vec4 qb,
                                 out point_vec4 qc, out point_vec4 ua, out point_vec4 ub, out point_vec4 uc,
                                 out point_vec4 va, out point_vec4 vb, out point_vec4 vc) {
  int k = nodes[node + 3];
  float w[16], ws[16], wt[16], d[4], scale;
  int first_row, steps;
  int n_rows = extraordinary_rows(quad, nodes[node + 1], u, v, false, first_row, steps, w, ws, wt, d, scale);
  int rows = nodes[node + 2] + first_row * k;
  // The anchor: the ring's point of the most precision, as heaviest_point() (its weights are
  // known only in the loop below).
  int anchor_point = nodes[node + 4];
  float most = -1.0;
  for (int i = 0; i < k; ++i) {
    int p = nodes[node + 4 + i];
    float trace = abs(point_precision_trace(p));
    anchor_point = trace > most ? p : anchor_point;
    most = max(most, trace);
  }
  g_anchor = point_anchor(anchor_point);
  qa = point_vec4(0.0); qb = point_vec4(0.0); qc = point_vec4(0.0);
  point_vec4 sa = point_vec4(0.0), sb = point_vec4(0.0), sc = point_vec4(0.0);
  point_vec4 ta = point_vec4(0.0), tb = point_vec4(0.0), tc = point_vec4(0.0);
  for (int i = 0; i < k; ++i) {
    float x = 0.0, x_s = 0.0, x_t = 0.0;
    for (int j = 0; j < n_rows; ++j) {
      float e = extraordinary_tables[rows + j * k + i];
      x += w[j] * e;
      x_s += ws[j] * e;
      x_t += wt[j] * e;
    }
    add_point(nodes[node + 4 + i], x, x_s, x_t, qa, qb, qc, sa, sb, sc, ta, tb, tc);
  }
  ua = scale * (d[0] * sa + d[1] * ta); ub = scale * (d[0] * sb + d[1] * tb); uc = scale * (d[0] * sc + d[1] * tc);
  va = scale * (d[2] * sa + d[3] * ta); vb = scale * (d[2] * sb + d[3] * tb); vc = scale * (d[2] * sc + d[3] * tc);
}

// Position and tangents (Eq. 3.12) of the limit surface at (u, v) of a patch; `leaf_kind` is the
// kind of the node that was evaluated (1 regular, 2 terminal, 3 extraordinary). With GPS_LEAVES_ONLY,
// for plans that hold no extraordinary node: a software driver runs every branch of a batch whose
// lanes disagree, and the exact node's branch is a good part of an evaluation's cost.
void evaluate_plan(int patch_id, vec2 uv, out vec3 mu, out vec3 mu_u, out vec3 mu_v, out int leaf_kind) {
  float scale;
  int kind, depth;
  int node = descend_plan(roots[patch_id], false, uv.x, uv.y, scale, kind, depth);
  leaf_kind = kind;
  point_vec4 qa, qb, qc, ua, ub, uc, va, vb, vc;
#ifndef GPS_LEAVES_ONLY
  if (kind == kNodeExtraordinary) {
    evaluate_extraordinary_node(node, true, uv.x, uv.y, qa, qb, qc, ua, ub, uc, va, vb, vc);
    dual_to_surface_in_double(qa, qb, qc, ua, ub, uc, va, vb, vc, scale, mu, mu_u, mu_v);
    return;
  }
#endif
  float w[16], wdu[16], wdv[16];
  int boundary = node_boundary(nodes[node]);
  quad_leaf_basis(kind, boundary, uv.x, uv.y, w, wdu, wdv);
  qa = point_vec4(0.0); qb = point_vec4(0.0); qc = point_vec4(0.0);
  ua = point_vec4(0.0); ub = point_vec4(0.0); uc = point_vec4(0.0);
  va = point_vec4(0.0); vb = point_vec4(0.0); vc = point_vec4(0.0);
  g_anchor = point_anchor(heaviest_point(node + 1, w));
  for (int k = 0; k < 16; ++k) add_point(nodes[node + 1 + k], w[k], wdu[k], wdv[k], qa, qb, qc, ua, ub, uc, va, vb, vc);
  dual_to_surface(qa, qb, qc, ua, ub, uc, va, vb, vc, scale, mu, mu_u, mu_v);
}
