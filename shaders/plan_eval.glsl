// The plans and their points (core/plan_table.h) and their evaluation; mirrors core/patch_eval.cpp.
// A 9D point q = (xx xy xz yy yz zz | b0 b1 b2) is three vec4: (xx xy xz yy) (yz zz b0 b1) (b2 0 0 0).
layout(std430, binding = kBindingPoints) readonly buffer Points { vec4 points[]; };
layout(std430, binding = kBindingNodes) readonly buffer Nodes { int nodes[]; };
layout(std430, binding = kBindingRoots) readonly buffer Roots { int roots[]; };
layout(std430, binding = kBindingCorners) readonly buffer CornerPoints { int corner_points[]; };
layout(std430, binding = kBindingPatchEdges) readonly buffer PatchEdges { int patch_edges[]; };  // quads: core/plan_table.h
layout(std430, binding = kBindingEvTables) readonly buffer EvTables { float ev_tables[]; };

mat3 precision_of(vec4 a, vec4 b) { return mat3(a.x, a.y, a.z, a.y, a.w, b.x, a.z, b.x, b.y); }
vec3 precision_mean_of(vec4 b, vec4 c) { return vec3(b.z, b.w, c.x); }

// μ of plan point p: solve [q̂] μ = q̄ (thesis Eq. 2.11).
vec3 point_mean(int p) {
  vec4 a = points[kVec4PerPoint * p], b = points[kVec4PerPoint * p + 1], c = points[kVec4PerPoint * p + 2];
  return inverse(precision_of(a, b)) * precision_mean_of(b, c);
}

// μ and its tangents (thesis Eq. 3.12) from q, q_u, q_v (three vec4 each), derivatives times `scale`:
// μ = [q̂]⁻¹ q̄, μ_u = [q̂]⁻¹ (q̄_u − [q̂_u] μ).
void dual_to_surface(vec4 qa, vec4 qb, vec4 qc, vec4 ua, vec4 ub, vec4 uc, vec4 va, vec4 vb, vec4 vc, float scale,
                     out vec3 mu, out vec3 mu_u, out vec3 mu_v) {
  mat3 sigma = inverse(precision_of(qa, qb));
  mu = sigma * precision_mean_of(qb, qc);
  mu_u = scale * (sigma * (precision_mean_of(ub, uc) - precision_of(ua, ub) * mu));
  mu_v = scale * (sigma * (precision_mean_of(vb, vc) - precision_of(va, vb) * mu));
}

// An extraordinary node (core/loop_ev_tables.h, core/quad_ev_tables.h) at (u, v) of its own domain:
// q and its u and v derivatives; mirrors evaluate_extraordinary in core/patch_eval.cpp.
void evaluate_extraordinary_node(int node, bool quad, float u, float v, out vec4 qa, out vec4 qb, out vec4 qc,
                                 out vec4 ua, out vec4 ub, out vec4 uc, out vec4 va, out vec4 vb, out vec4 vc) {
  int r = nodes[node + 1], table = nodes[node + 2], k = nodes[node + 3], net = quad ? 16 : 12;
  float s, t, scale, d[4];
  int block;
  if (quad) {
    quad_turn_to_corner(r, u, v, s, t);
    quad_turned_derivative_coefficients(r, d);
    block = quad_ev_locate(s, t, scale);
  } else {
    triangle_turn_to_corner(r, u, v, s, t);
    triangle_turned_derivative_coefficients(r, d);
    block = loop_ev_locate(s, t, scale);
  }
  float w[16], ws[16], wt[16];
  int rows, n_rows;
  if (block >= 0) {
    if (quad) bspline_patch_basis(s, t, w, ws, wt);
    else {
      float w12[12], ws12[12], wt12[12];
      loop_box_spline_basis(s, t, w12, ws12, wt12);
      for (int j = 0; j < 12; ++j) { w[j] = w12[j]; ws[j] = ws12[j]; wt[j] = wt12[j]; }
    }
    rows = table + net * block * k;
    n_rows = net;
  } else {  // the limit masks: position, d/ds, d/dt
    for (int j = 0; j < 3; ++j) { w[j] = j == 0 ? 1.0 : 0.0; ws[j] = j == 1 ? 1.0 : 0.0; wt[j] = j == 2 ? 1.0 : 0.0; }
    rows = table + 3 * net * kEvLevels * k;
    n_rows = 3;
    scale = 1.0;
  }
  qa = vec4(0.0); qb = vec4(0.0); qc = vec4(0.0);
  vec4 sa = vec4(0.0), sb = vec4(0.0), sc = vec4(0.0), ta = vec4(0.0), tb = vec4(0.0), tc = vec4(0.0);
  for (int i = 0; i < k; ++i) {
    float x = 0.0, x_s = 0.0, x_t = 0.0;
    for (int j = 0; j < n_rows; ++j) {
      float e = ev_tables[rows + j * k + i];
      x += w[j] * e;
      x_s += ws[j] * e;
      x_t += wt[j] * e;
    }
    int p = nodes[node + 4 + i];
    vec4 a = points[kVec4PerPoint * p], b = points[kVec4PerPoint * p + 1], c = points[kVec4PerPoint * p + 2];
    qa += x * a; qb += x * b; qc += x * c;
    sa += x_s * a; sb += x_s * b; sc += x_s * c;
    ta += x_t * a; tb += x_t * b; tc += x_t * c;
  }
  ua = scale * (d[0] * sa + d[1] * ta); ub = scale * (d[0] * sb + d[1] * tb); uc = scale * (d[0] * sc + d[1] * tc);
  va = scale * (d[2] * sa + d[3] * ta); vb = scale * (d[2] * sb + d[3] * tb); vc = scale * (d[2] * sc + d[3] * tc);
}

// Position and tangents (Eq. 3.12) of the limit surface at (u, v) of a patch; `leaf_kind` is the
// kind of the node that was evaluated (1 regular, 2 terminal, 3 extraordinary).
void evaluate_plan(int patch_id, vec2 uv, out vec3 mu, out vec3 mu_u, out vec3 mu_v, out int leaf_kind) {
  int node = roots[patch_id];
  float scale = 1.0;
  // The kind is read into a variable once per node: re-reading nodes[node] after the loop gave the
  // stale value on Mesa 22.3 llvmpipe (caught by test_surface_renderer). The loop is bounded (plans
  // are at most 8 deep): after a divergent while loop, llvmpipe ran the extraordinary node's loops
  // with wrong values.
  int kind = nodes[node];
  for (int depth = 0; depth < 8 && kind == kNodeInternal; ++depth) {
    int ubit = uv.x >= 0.5 ? 1 : 0, vbit = uv.y >= 0.5 ? 1 : 0;
    uv = 2.0 * uv - vec2(ubit, vbit);
    scale *= 2.0;
    node = nodes[node + 1 + ubit + 2 * vbit];
    kind = nodes[node];
  }
  leaf_kind = kind;
  vec4 qa, qb, qc, ua, ub, uc, va, vb, vc;
  if (kind == kNodeExtraordinary) {
    evaluate_extraordinary_node(node, true, uv.x, uv.y, qa, qb, qc, ua, ub, uc, va, vb, vc);
    dual_to_surface(qa, qb, qc, ua, ub, uc, va, vb, vc, scale, mu, mu_u, mu_v);
    return;
  }
  float wu[4], dwu[4], wv[4], dwv[4];
  if (kind == kNodeRegular) {
    bspline_basis(uv.x, wu, dwu);
    bspline_basis(uv.y, wv, dwv);
  } else {
    bezier_basis(uv.x, wu, dwu);
    bezier_basis(uv.y, wv, dwv);
  }
  qa = vec4(0.0); qb = vec4(0.0); qc = vec4(0.0);
  ua = vec4(0.0); ub = vec4(0.0); uc = vec4(0.0);
  va = vec4(0.0); vb = vec4(0.0); vc = vec4(0.0);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      int p = nodes[node + 1 + i + 4 * j];
      vec4 a = points[kVec4PerPoint * p], b = points[kVec4PerPoint * p + 1], c = points[kVec4PerPoint * p + 2];
      float w = wu[i] * wv[j], wdu = dwu[i] * wv[j], wdv = wu[i] * dwv[j];
      qa += w * a; qb += w * b; qc += w * c;
      ua += wdu * a; ub += wdu * b; uc += wdu * c;
      va += wdv * a; vb += wdv * b; vc += wdv * c;
    }
  dual_to_surface(qa, qb, qc, ua, ub, uc, va, vb, vc, scale, mu, mu_u, mu_v);
}
