// The plans and their points (core/plan_table.h) and their evaluation; mirrors core/patch_eval.cpp.
// A 9D point q = (xx xy xz yy yz zz | b0 b1 b2) is three vec4: (xx xy xz yy) (yz zz b0 b1) (b2 0 0 0).
layout(std430, binding = kBindingPoints) readonly buffer Points { vec4 points[]; };
layout(std430, binding = kBindingNodes) readonly buffer Nodes { int nodes[]; };
layout(std430, binding = kBindingRoots) readonly buffer Roots { int roots[]; };
layout(std430, binding = kBindingCorners) readonly buffer CornerPoints { int corner_points[]; };
layout(std430, binding = kBindingPatchEdges) readonly buffer PatchEdges { int patch_edges[]; };  // quads: core/plan_table.h

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

// Position and tangents (Eq. 3.12) of the limit surface at (u, v) of a patch; `leaf_kind` is the
// kind of the node that was evaluated (1 regular, 2 terminal).
void evaluate_plan(int patch_id, vec2 uv, out vec3 mu, out vec3 mu_u, out vec3 mu_v, out int leaf_kind) {
  int node = roots[patch_id];
  float scale = 1.0;
  // The kind is read into a variable once per node: re-reading nodes[node] after the loop gave the
  // stale value on Mesa 22.3 llvmpipe (caught by test_surface_renderer).
  int kind = nodes[node];
  while (kind == kNodeInternal) {
    int ubit = uv.x >= 0.5 ? 1 : 0, vbit = uv.y >= 0.5 ? 1 : 0;
    uv = 2.0 * uv - vec2(ubit, vbit);
    scale *= 2.0;
    node = nodes[node + 1 + ubit + 2 * vbit];
    kind = nodes[node];
  }
  leaf_kind = kind;
  float wu[4], dwu[4], wv[4], dwv[4];
  if (kind == kNodeRegular) {
    bspline_basis(uv.x, wu, dwu);
    bspline_basis(uv.y, wv, dwv);
  } else {
    bezier_basis(uv.x, wu, dwu);
    bezier_basis(uv.y, wv, dwv);
  }
  vec4 qa = vec4(0.0), qb = vec4(0.0), qc = vec4(0.0);
  vec4 ua = vec4(0.0), ub = vec4(0.0), uc = vec4(0.0);
  vec4 va = vec4(0.0), vb = vec4(0.0), vc = vec4(0.0);
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
