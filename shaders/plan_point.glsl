// A plan point q = (q̂, q̄) is kept on the GPU about an anchor a, a mean near it: three vec4
// (xx xy xz yy) (yz zz y0 y1) (y2 a0 a1 a2) with y = q̄ − q̂ a (gpu_layout.h). A base vertex is
// (Σ⁻¹, 0, μ). Sums are taken about one anchor c: Σ w q̄ = Σ w (y + q̂ (a − c)) + (Σ w q̂) c, exact
// since q is linear. In float, q̄ = q̂ μ of a thin Gaussian (q̂ ~ 1e6) far from the origin keeps few
// digits of the surface's shape near it; y about a nearby anchor keeps them (the pawn's thin poles
// need them for their normals). Points that are not Gaussians (boundary rows with negative weights)
// are kept the same way. Kept in double (point_real, gpu_layout.h), a needle of condition 1e12 still
// needs the anchor: q̄ = q̂ μ rounds to κ times double's precision in its long direction.
// The including shader declares the Points buffer.
point_mat3 precision_of(point_vec4 a, point_vec4 b) {
  return point_mat3(a.x, a.y, a.z, a.y, a.w, b.x, a.z, b.x, b.y);
}
point_vec3 offset_part(point_vec4 b, point_vec4 c) { return point_vec3(b.z, b.w, c.x); }

point_vec3 point_anchor(int p) { return points[kVec4PerPoint * p + 2].yzw; }

// [q̂]⁻¹ b by q̂ = L D Lᵀ, backward stable: where q̂ has condition κ its solution loses about κ times
// the precision in q̂'s weak directions. inverse() divides the adjugate by the determinant, both sums
// that cancel: a Gaussian thin in one direction (q̂ near rank one, as sums of discs of one orientation
// stay) lost κ² times it, and at κ 7e5 its float surface spiked out of the frame.
#define GPS_PRECISION_SOLVE(mat, vec)                                               \
  vec precision_solve(mat q, vec b) {                                               \
    vec l = vec(q[0][1], q[0][2], 0.0) / q[0][0]; /* l10, l20; l21 below */        \
    vec d = vec(q[0][0], q[1][1] - l.x * q[0][1], 0.0);                              \
    l.z = (q[1][2] - l.y * q[0][1]) / d.y;                                           \
    d.z = q[2][2] - l.y * q[0][2] - l.z * l.z * d.y;                                 \
    vec z = vec(b.x, b.y - l.x * b.x, 0.0);                                          \
    z.z = b.z - l.y * z.x - l.z * z.y;                                               \
    z /= d;                                                                          \
    z.y -= l.z * z.z;                                                                \
    z.x -= l.x * z.y + l.y * z.z;                                                    \
    return z;                                                                        \
  }
GPS_PRECISION_SOLVE(mat3, vec3)
GPS_PRECISION_SOLVE(dmat3, dvec3)

// tr q̂ of plan point p: how heavily it weighs in a sum, for the choice of the sum's anchor.
float point_precision_trace(int p) {
  point_vec4 a = points[kVec4PerPoint * p], b = points[kVec4PerPoint * p + 1];
  return float(a.x + a.w + b.y);
}

// μ of plan point p: a + [q̂]⁻¹ y (thesis Eq. 2.11 about the anchor).
vec3 point_mean(int p) {
  point_vec4 a = points[kVec4PerPoint * p], b = points[kVec4PerPoint * p + 1], c = points[kVec4PerPoint * p + 2];
  return vec3(c.yzw + precision_solve(precision_of(a, b), offset_part(b, c)));
}

// Plan point p about `anchor`: (q̂, y + q̂ (a − anchor)) in the first nine floats; the tenth to twelfth
// are zero, so that sums of them are sums of 9D points.
void anchored_point(int p, point_vec3 anchor, out point_vec4 a, out point_vec4 b, out point_vec4 c) {
  a = points[kVec4PerPoint * p];
  b = points[kVec4PerPoint * p + 1];
  c = points[kVec4PerPoint * p + 2];
  point_vec3 y = offset_part(b, c) + precision_of(a, b) * (c.yzw - anchor);
  b.zw = y.xy;
  c = point_vec4(y.z, 0.0, 0.0, 0.0);
}
