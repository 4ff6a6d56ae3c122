// Triangle plans (Loop): descent (core/plans/plan_descent.h), box-spline nodes and exact extraordinary nodes
// (evaluate_extraordinary_node in plan_eval.glsl); mirrors evaluate_dual in core/evaluation/patch_eval.cpp.

void evaluate_triangle_plan(int patch_id, float patch_u, float patch_v, out vec3 mu, out vec3 mu_u, out vec3 mu_v, out int leaf_kind) {
  float u = patch_u, v = patch_v, scale;
  int kind, depth;
  int node = descend_plan(roots[patch_id], true, u, v, scale, kind, depth);
  leaf_kind = kind;
  point_vec4 qa = point_vec4(0.0), qb = point_vec4(0.0), qc = point_vec4(0.0);
  point_vec4 ua = point_vec4(0.0), ub = point_vec4(0.0), uc = point_vec4(0.0);
  point_vec4 va = point_vec4(0.0), vb = point_vec4(0.0), vc = point_vec4(0.0);
  float w[12], ws[12], wt[12];
#ifndef GPS_LEAVES_ONLY  // plans without extraordinary nodes (plan_eval.glsl, evaluate_plan)
  if (kind == kNodeRegular) {
#endif
    loop_box_spline_basis(u, v, w, ws, wt);
    g_anchor = point_anchor(heaviest_point(node + 1, w));
    for (int j = 0; j < 12; ++j) add_point(nodes[node + 1 + j], w[j], ws[j], wt[j], qa, qb, qc, ua, ub, uc, va, vb, vc);
    dual_to_surface(qa, qb, qc, ua, ub, uc, va, vb, vc, scale, mu, mu_u, mu_v);
#ifndef GPS_LEAVES_ONLY
    return;
  }
  evaluate_extraordinary_node(node, false, u, v, qa, qb, qc, ua, ub, uc, va, vb, vc);
  dual_to_surface_in_double(qa, qb, qc, ua, ub, uc, va, vb, vc, scale, mu, mu_u, mu_v);
#endif
}
