// Triangle plans (Loop): descent, box-spline nodes and exact extraordinary nodes
// (core/loop_ev_tables.h); mirrors evaluate_triangle_dual in core/patch_eval.cpp.
layout(std430, binding = kBindingEvTables) readonly buffer EvTables { float ev_tables[]; };

void evaluate_triangle_plan(int patch_id, float patch_u, float patch_v, out vec3 mu, out vec3 mu_u, out vec3 mu_v, out int leaf_kind) {
  float u = patch_u, v = patch_v;
  int node = roots[patch_id];
  float scale = 1.0;
  int kind = nodes[node];  // read once per node (see evaluate_plan)
  for (int depth = 0; depth < 8 && kind == kNodeInternal; ++depth) {  // triangle plans are one level deep
    float sign;
    int child = triangle_child(u, v, sign);
    scale *= 2.0 * sign;
    node = nodes[node + 1 + child];
    kind = nodes[node];
  }
  leaf_kind = kind;
  vec4 qa = vec4(0.0), qb = vec4(0.0), qc = vec4(0.0);
  vec4 ua = vec4(0.0), ub = vec4(0.0), uc = vec4(0.0);
  vec4 va = vec4(0.0), vb = vec4(0.0), vc = vec4(0.0);
  float w[12], ws[12], wt[12];
  if (kind == kNodeRegular) {
    loop_box_spline_basis(u, v, w, ws, wt);
    for (int j = 0; j < 12; ++j) {
      int p = nodes[node + 1 + j];
      vec4 a = points[kVec4PerPoint * p], b = points[kVec4PerPoint * p + 1], c = points[kVec4PerPoint * p + 2];
      qa += w[j] * a; qb += w[j] * b; qc += w[j] * c;
      ua += ws[j] * a; ub += ws[j] * b; uc += ws[j] * c;
      va += wt[j] * a; vb += wt[j] * b; vc += wt[j] * c;
    }
    dual_to_surface(qa, qb, qc, ua, ub, uc, va, vb, vc, scale, mu, mu_u, mu_v);
    return;
  }
  int r = nodes[node + 1], table = nodes[node + 2], k = nodes[node + 3];
  float s, t, ev_scale;
  triangle_turn_to_corner(r, u, v, s, t);
  int block = loop_ev_locate(s, t, ev_scale);
  int rows, n_rows;
  if (block >= 0) {
    loop_box_spline_basis(s, t, w, ws, wt);
    rows = table + 12 * block * k;
    n_rows = 12;
  } else {  // the limit masks: position, d/ds, d/dt
    for (int j = 0; j < 3; ++j) { w[j] = j == 0 ? 1.0 : 0.0; ws[j] = j == 1 ? 1.0 : 0.0; wt[j] = j == 2 ? 1.0 : 0.0; }
    rows = table + 36 * kEvLevels * k;
    n_rows = 3;
    ev_scale = 1.0;
  }
  // (ua, ub, uc) and (va, vb, vc) hold the s and t derivatives here.
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
    ua += x_s * a; ub += x_s * b; uc += x_s * c;
    va += x_t * a; vb += x_t * b; vc += x_t * c;
  }
  float d[4];
  triangle_turned_derivative_coefficients(r, d);
  vec4 sa = ua, sb = ub, sc = uc;
  ua = ev_scale * (d[0] * sa + d[1] * va); ub = ev_scale * (d[0] * sb + d[1] * vb); uc = ev_scale * (d[0] * sc + d[1] * vc);
  va = ev_scale * (d[2] * sa + d[3] * va); vb = ev_scale * (d[2] * sb + d[3] * vb); vc = ev_scale * (d[2] * sc + d[3] * vc);
  dual_to_surface(qa, qb, qc, ua, ub, uc, va, vb, vc, scale, mu, mu_u, mu_v);
}
