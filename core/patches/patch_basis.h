// The bases of the patches in a plan and the descent through triangle nodes: ONE source, compiled
// as C++ (namespace gps, double) and, with GPS_GLSL defined, embedded into the shaders as GLSL
// (float) by cmake/embed_shaders.cmake, as OpenSubdiv does with osd/patchBasis.h. Keep to the
// common subset of both languages: the macros below cover parameters, constants and arrays.
#ifndef GPS_GLSL
#pragma once
#include <algorithm>
#include <cmath>
namespace gps {
#define GPS_REAL double
#define GPS_MAX std::max
#define GPS_LDEXP std::ldexp
#define GPS_EXPONENT(x, e) std::frexp(x, &e)
#define GPS_FN inline
#define GPS_CONST inline constexpr
#define GPS_OUT               // arrays are passed by pointer in C++
#define GPS_INOUT
#define GPS_OUT_REF(T) T&
#define GPS_INOUT_REF(T) T&
#else
#define GPS_REAL float
#define GPS_MAX max
#define GPS_LDEXP ldexp
#define GPS_EXPONENT(x, e) frexp(x, e)
#define GPS_FN
#define GPS_CONST const
#define GPS_OUT out
#define GPS_INOUT inout
#define GPS_OUT_REF(T) out T
#define GPS_INOUT_REF(T) inout T
#endif

// Node kinds of core/plans/patch_plans.h (C++: the values of NodeKind).
GPS_CONST int kNodeInternal = 0;
GPS_CONST int kNodeRegular = 1;       // quads: bicubic B-spline; triangles: Loop's quartic box spline
GPS_CONST int kNodeTerminal = 2;      // quads: bicubic Bézier from the rules of thesis Fig. 2.5
GPS_CONST int kNodeExtraordinary = 3; // exact evaluation at an extraordinary corner (both shapes)
// Patch edges of quad patches (core/plans/patch_plans.h, PatchEdge): kPatchEdgeInts ints per edge (from, to,
// part), four edges per patch; the parts are PatchEdgePart's values.
GPS_CONST int kPatchEdgeInts = 3;
GPS_CONST int kPatchEdgeStride = 4 * kPatchEdgeInts;
GPS_CONST int kEdgeWhole = 0;             // all of the edge, and so is the patch beside it
GPS_CONST int kEdgeWholeBesideHalves = 1; // all of the edge; the other side is split into two halves
GPS_CONST int kEdgeFirstHalf = 2;         // the half at `from`
GPS_CONST int kEdgeSecondHalf = 3;        // the half at `to`
/// Whether a patch whose edge 0 is this part is half-size: a patch of a split face (one Catmull-Clark
/// step down), whose edge 0 is half of the face's edge.
GPS_FN bool half_size_part(int edge0_part) { return edge0_part == kEdgeFirstHalf || edge0_part == kEdgeSecondHalf; }
// Flags of the patch adjacency records (core/plans/patch_adjacency.h), on an infinitely sharp crease
// of the surface, where each side has its own normal: in a patch edge's neighbour code (edge index
// plus kNeighbourReversed) and in a patch corner's owner corner index.
GPS_CONST int kNeighbourEdgeMask = 3;
GPS_CONST int kNeighbourReversed = 4;
GPS_CONST int kNeighbourSharpEdge = 8;   // the patch edge lies on an infinitely sharp crease
GPS_CONST int kOwnerCornerMask = 3;
GPS_CONST int kOwnerSharpCorner = 4;     // the normals of the patches around the corner differ
// Levels of the extraordinary tables (core/extraordinary/loop_extraordinary_tables.h,
// core/extraordinary/quad_extraordinary_tables.h). Tessellation at integer levels up to 64 puts no
// point closer to a corner than 1/64 of its patch (s + t and max(s, t) ≥ 1/64 for Loop's and
// Catmull-Clark's locate): levels 0..5, and one more against float rounding. Closer points take the
// level-(kExtraordinaryLevels − 1) block after further steps of the table's subdivision matrix A (on
// the CPU; the GPU takes the limit point there).
GPS_CONST int kExtraordinaryLevels = 7;

/// Uniform cubic B-spline basis on one segment, t in [0,1]: values w[0..3] and derivatives dw[0..3].
GPS_FN void bspline_basis(GPS_REAL t, GPS_OUT GPS_REAL w[4], GPS_OUT GPS_REAL dw[4]) {
  GPS_REAL s = 1.0 - t, t2 = t * t;
  w[0] = s * s * s / 6.0;
  w[1] = (3.0 * t2 * t - 6.0 * t2 + 4.0) / 6.0;
  w[2] = (-3.0 * t2 * t + 3.0 * t2 + 3.0 * t + 1.0) / 6.0;
  w[3] = t2 * t / 6.0;
  dw[0] = -0.5 * s * s;
  dw[1] = 1.5 * t2 - 2.0 * t;
  dw[2] = -1.5 * t2 + t + 0.5;
  dw[3] = 0.5 * t2;
}

/// Cubic Bernstein basis, t in [0,1]: values w[0..3] and derivatives dw[0..3].
GPS_FN void bezier_basis(GPS_REAL t, GPS_OUT GPS_REAL w[4], GPS_OUT GPS_REAL dw[4]) {
  GPS_REAL s = 1.0 - t;
  w[0] = s * s * s;
  w[1] = 3.0 * t * s * s;
  w[2] = 3.0 * t * t * s;
  w[3] = t * t * t;
  dw[0] = -3.0 * s * s;
  dw[1] = 3.0 * s * s - 6.0 * t * s;
  dw[2] = 6.0 * t * s - 3.0 * t * t;
  dw[3] = 3.0 * t * t;
}

// Boundary edges of a regular quad leaf, as bits: 1 (v = 0, edge 0), 2 (u = 1), 4 (v = 1), 8 (u = 0),
// kept in its record's first word above the kind (kNodeKindBits). Beyond a boundary edge the
// B-spline net has phantom points p₋₁ = 2p₀ − p₁ (mirrored across it); the leaf's net holds the
// real point p₀ in their slots instead and the basis takes them in (bspline_fold_boundary), so no
// point of the net is a large difference that float sums cancel.
GPS_CONST int kBoundaryV0 = 1;
GPS_CONST int kBoundaryU1 = 2;
GPS_CONST int kBoundaryV1 = 4;
GPS_CONST int kBoundaryU0 = 8;
GPS_CONST int kNodeKindBits = 4;  // a node record's first word: kind | boundary << kNodeKindBits
GPS_FN int node_kind(int word) { return word & ((1 << kNodeKindBits) - 1); }
GPS_FN int node_boundary(int word) { return word >> kNodeKindBits; }

/// One direction's B-spline basis b (and db) with the phantom points beyond the low (b[0]) or high
/// (b[3]) end taken in: p₋₁ = 2p₀ − p₁ gives p₀ 2·b[0] more and p₁ b[0] less, and its own slot 0.
GPS_FN void bspline_fold_boundary(bool low, bool high, GPS_INOUT GPS_REAL b[4], GPS_INOUT GPS_REAL db[4]) {
  if (low) {
    b[1] += 2.0 * b[0]; b[2] -= b[0]; b[0] = 0.0;
    db[1] += 2.0 * db[0]; db[2] -= db[0]; db[0] = 0.0;
  }
  if (high) {
    b[2] += 2.0 * b[3]; b[1] -= b[3]; b[3] = 0.0;
    db[2] += 2.0 * db[3]; db[1] -= db[3]; db[3] = 0.0;
  }
}

/// A quad leaf of a plan at (u, v): weights w[i + 4j] of its 16 points (i along u) and their u and
/// v derivatives; a regular node is a bicubic B-spline patch, a terminal node a bicubic Bézier patch;
/// `boundary`: a regular node's boundary bits (kBoundaryV0 …), whose phantom points the basis takes in.
GPS_FN void quad_leaf_basis(int kind, int boundary, GPS_REAL u, GPS_REAL v, GPS_OUT GPS_REAL w[16], GPS_OUT GPS_REAL du[16],
                            GPS_OUT GPS_REAL dv[16]) {
  GPS_REAL wu[4], dwu[4], wv[4], dwv[4];
  if (kind == kNodeRegular) {
    bspline_basis(u, wu, dwu);
    bspline_basis(v, wv, dwv);
    bspline_fold_boundary((boundary & kBoundaryU0) != 0, (boundary & kBoundaryU1) != 0, wu, dwu);
    bspline_fold_boundary((boundary & kBoundaryV0) != 0, (boundary & kBoundaryV1) != 0, wv, dwv);
  } else {
    bezier_basis(u, wu, dwu);
    bezier_basis(v, wv, dwv);
  }
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      w[i + 4 * j] = wu[i] * wv[j];
      du[i + 4 * j] = dwu[i] * wv[j];
      dv[i + 4 * j] = wu[i] * dwv[j];
    }
}

// Loop's regular patch (Stam 1998, "Evaluation of Loop subdivision surfaces"): the quartic box
// spline over a triangle (v0, v1, v2) = lattice points (0,0), (1,0), (0,1), parameters (u, v) with
// barycentrics (1−u−v, u, v). Its 12 control points are the lattice points of the three corners'
// 1-rings, in this order: (0,0) (1,0) (0,1) (−1,0) (0,−1) (1,−1) (−1,1) (2,−1) (2,0) (1,1) (0,2) (−1,2).
// The patch is a quartic Bézier triangle whose 15 ordinates b_ab (weight of u^a v^b w^(4−a−b), rows
// in the order b = 0..4, a = 0..4−b) are these combinations of the 12 control points, times 1/24;
// tests/core/test_loop_plans.cpp checks the basis against Loop subdivision and limit projection.
#ifdef GPS_GLSL
const float kLoopBezier[180] = float[180](
#else
inline constexpr double kLoopBezier[180] = {
#endif
  12, 2, 2, 2, 2, 2, 2, 0, 0, 0, 0, 0,
  12, 4, 3, 0, 1, 3, 1, 0, 0, 0, 0, 0,
  8, 8, 4, 0, 0, 4, 0, 0, 0, 0, 0, 0,
  4, 12, 3, 0, 0, 3, 0, 1, 0, 1, 0, 0,
  2, 12, 2, 0, 0, 2, 0, 2, 2, 2, 0, 0,
  12, 3, 4, 1, 0, 1, 3, 0, 0, 0, 0, 0,
  10, 6, 6, 0, 0, 1, 1, 0, 0, 0, 0, 0,
  6, 10, 6, 0, 0, 1, 0, 0, 0, 1, 0, 0,
  3, 12, 4, 0, 0, 1, 0, 0, 1, 3, 0, 0,
  8, 4, 8, 0, 0, 0, 4, 0, 0, 0, 0, 0,
  6, 6, 10, 0, 0, 0, 1, 0, 0, 1, 0, 0,
  4, 8, 8, 0, 0, 0, 0, 0, 0, 4, 0, 0,
  4, 3, 12, 0, 0, 0, 3, 0, 0, 1, 0, 1,
  3, 4, 12, 0, 0, 0, 1, 0, 0, 3, 1, 0,
  2, 2, 12, 0, 0, 0, 2, 0, 0, 2, 2, 2
#ifdef GPS_GLSL
);
#else
};
#endif

/// Loop's box-spline basis at (u, v): weights w[0..11] of the 12 control points and their u and v
/// derivatives, through the quartic Bernstein polynomials B_ab = 4!/(a! b! c!) u^a v^b w^c, c = 4−a−b.
GPS_FN void loop_box_spline_basis(GPS_REAL u, GPS_REAL v, GPS_OUT GPS_REAL w[12], GPS_OUT GPS_REAL du[12],
                                  GPS_OUT GPS_REAL dv[12]) {
  GPS_REAL t = 1.0 - u - v;
  GPS_REAL pu[5], pv[5], pt[5];  // powers 0..4
  pu[0] = 1.0; pv[0] = 1.0; pt[0] = 1.0;
  for (int i = 1; i < 5; ++i) {
    pu[i] = pu[i - 1] * u;
    pv[i] = pv[i - 1] * v;
    pt[i] = pt[i - 1] * t;
  }
  for (int k = 0; k < 12; ++k) {
    w[k] = 0.0;
    du[k] = 0.0;
    dv[k] = 0.0;
  }
  for (int row = 0; row < 15; ++row) {
      int b = row < 5 ? 0 : row < 9 ? 1 : row < 12 ? 2 : row < 14 ? 3 : 4;
      int a = row - (b * 5 - (b * (b - 1)) / 2);
      int c = 4 - a - b;
      // multinomial 4!/(a! b! c!) from the exponents
      GPS_REAL m = 24.0;
      for (int i = 2; i <= a; ++i) m /= GPS_REAL(i);
      for (int i = 2; i <= b; ++i) m /= GPS_REAL(i);
      for (int i = 2; i <= c; ++i) m /= GPS_REAL(i);
      GPS_REAL value = m * pu[a] * pv[b] * pt[c];
      // d/du and d/dv of u^a v^b (1−u−v)^c; a zero exponent's factor is 0 (indices kept in range:
      // Mesa's llvmpipe reads out of range when a select of the two branches is compiled).
      int a1 = a > 0 ? a - 1 : 0, b1 = b > 0 ? b - 1 : 0, c1 = c > 0 ? c - 1 : 0;
      GPS_REAL d_t = m * GPS_REAL(c) * pu[a] * pv[b] * pt[c1];
      GPS_REAL value_u = m * GPS_REAL(a) * pu[a1] * pv[b] * pt[c] - d_t;
      GPS_REAL value_v = m * GPS_REAL(b) * pu[a] * pv[b1] * pt[c] - d_t;
      for (int k = 0; k < 12; ++k) {
        GPS_REAL x = kLoopBezier[12 * row + k] / 24.0;
        w[k] += x * value;
        du[k] += x * value_u;
        dv[k] += x * value_v;
      }
  }
}

/// One step down a triangle node (core/plans/patch_plans.h): the child under (u, v) — 0 at corner 0
/// (u + v < ½), 1 at corner 1 (u ≥ ½), 2 at corner 2 (v ≥ ½), 3 the middle triangle, turned by a
/// half turn — with (u, v) mapped into the child's domain; `sign` (±1) times 2 is d(child)/d(node).
GPS_FN int triangle_child(GPS_INOUT_REF(GPS_REAL) u, GPS_INOUT_REF(GPS_REAL) v, GPS_OUT_REF(GPS_REAL) sign) {
  sign = 1.0;
  if (u + v < 0.5) {
    u = 2.0 * u;
    v = 2.0 * v;
    return 0;
  }
  if (u >= 0.5) {
    u = 2.0 * u - 1.0;
    v = 2.0 * v;
    return 1;
  }
  if (v >= 0.5) {
    u = 2.0 * u;
    v = 2.0 * v - 1.0;
    return 2;
  }
  u = 1.0 - 2.0 * u;
  v = 1.0 - 2.0 * v;
  sign = -1.0;
  return 3;
}

/// Parameters (s, t) of a triangle node turned so that its corner r is corner 0: barycentrics
/// (b0, b1, b2) = (1−u−v, u, v) become s = b_{r+1}, t = b_{r+2}.
GPS_FN void triangle_turn_to_corner(int r, GPS_REAL u, GPS_REAL v, GPS_OUT_REF(GPS_REAL) s, GPS_OUT_REF(GPS_REAL) t) {
  GPS_REAL b0 = 1.0 - u - v;
  if (r == 0) { s = u; t = v; }
  else if (r == 1) { s = v; t = b0; }
  else { s = b0; t = u; }
}

/// Derivatives back from (s, t) of triangle_turn_to_corner() to (u, v): d/du, d/dv of a function with
/// derivatives (f_s, f_t), as coefficients: d/du = a_s f_s + a_t f_t, d/dv = b_s f_s + b_t f_t.
GPS_FN void triangle_turned_derivative_coefficients(int r, GPS_OUT GPS_REAL c[4]) {
  if (r == 0) { c[0] = 1.0; c[1] = 0.0; c[2] = 0.0; c[3] = 1.0; }
  else if (r == 1) { c[0] = 0.0; c[1] = -1.0; c[2] = 1.0; c[3] = -1.0; }
  else { c[0] = -1.0; c[1] = 1.0; c[2] = -1.0; c[3] = 0.0; }
}

/// The halvings n ≥ 0 toward an extraordinary corner after which x · 2ⁿ ≥ ½ (x: the distance measure
/// of a locate step, in [0, 2]), or −1 at the corner (x = 0): there the limit masks apply. From x's
/// binary exponent (x = m · 2^e, ½ ≤ m < 1: n = −e), no loop.
GPS_FN int extraordinary_halvings(GPS_REAL x) {
  int e = 0;
  GPS_EXPONENT(x, e);
  if (x <= 0.0) return -1;
  return e >= 0 ? 0 : -e;
}

/// The table block 3n + c − 1 of a point n halvings down in child c, the levels past the table's
/// last taken as `steps` more applications of its subdivision matrix A to the node's points.
GPS_FN int extraordinary_block(int n, int child, GPS_OUT_REF(int) steps) {
  steps = GPS_MAX(n - (kExtraordinaryLevels - 1), 0);
  return 3 * (n - steps) + child - 1;
}

/// Where (s, t) of an extraordinary node falls (Stam 1998, §3), its extraordinary vertex at
/// (0, 0): after n halvings toward that corner, in child c = 1..3 of triangle_child() at the new
/// (s, t). Returns the table block of extraordinary_block()
/// (core/extraordinary/loop_extraordinary_tables.h), or −1 at the corner (there the limit masks
/// apply); `scale` = d(new s, t)/d(s, t).
GPS_FN int loop_extraordinary_locate(GPS_INOUT_REF(GPS_REAL) s, GPS_INOUT_REF(GPS_REAL) t, GPS_OUT_REF(GPS_REAL) scale,
                          GPS_OUT_REF(int) steps) {
  // n = the halvings that bring s + t to at least ½, read off its binary exponent (doubling is
  // exact, so this equals halving step by step); then that many doublings of s and t by ldexp.
  scale = 1.0;
  steps = 0;
  int n = extraordinary_halvings(s + t);
  if (n < 0) return -1;
  s = GPS_LDEXP(s, n);
  t = GPS_LDEXP(t, n);
  GPS_REAL sign = 1.0;
  int child = triangle_child(s, t, sign);
  scale = 2.0 * sign * GPS_LDEXP(GPS_REAL(1.0), n);
  return extraordinary_block(n, child, steps);
}

/// Parameters (s, t) of a quad node turned so that its corner r is corner 0 (corners k at (0,0),
/// (1,0), (1,1), (0,1)): s runs toward corner r + 1, t toward corner r + 3; a rotation.
GPS_FN void quad_turn_to_corner(int r, GPS_REAL u, GPS_REAL v, GPS_OUT_REF(GPS_REAL) s, GPS_OUT_REF(GPS_REAL) t) {
  if (r == 0) { s = u; t = v; }
  else if (r == 1) { s = v; t = 1.0 - u; }
  else if (r == 2) { s = 1.0 - u; t = 1.0 - v; }
  else { s = 1.0 - v; t = u; }
}

/// Derivatives back from (s, t) of quad_turn_to_corner() to (u, v), as in
/// triangle_turned_derivative_coefficients(): d/du = c[0] f_s + c[1] f_t, d/dv = c[2] f_s + c[3] f_t.
GPS_FN void quad_turned_derivative_coefficients(int r, GPS_OUT GPS_REAL c[4]) {
  if (r == 0) { c[0] = 1.0; c[1] = 0.0; c[2] = 0.0; c[3] = 1.0; }
  else if (r == 1) { c[0] = 0.0; c[1] = -1.0; c[2] = 1.0; c[3] = 0.0; }
  else if (r == 2) { c[0] = -1.0; c[1] = 0.0; c[2] = 0.0; c[3] = -1.0; }
  else { c[0] = 0.0; c[1] = 1.0; c[2] = -1.0; c[3] = 0.0; }
}

/// Where (s, t) of a quad extraordinary node falls (Stam 1998), its extraordinary vertex at (0, 0):
/// after n halvings toward that corner, in quadrant c = 1 (s ≥ ½ > t), 2 (both ≥ ½) or 3 (t ≥ ½ > s)
/// at the quadrant's own (s, t). Returns the table block of extraordinary_block()
/// (core/extraordinary/quad_extraordinary_tables.h), or −1 at the corner (there the limit masks
/// apply); `scale` = d(new s, t)/d(s, t).
GPS_FN int quad_extraordinary_locate(GPS_INOUT_REF(GPS_REAL) s, GPS_INOUT_REF(GPS_REAL) t, GPS_OUT_REF(GPS_REAL) scale,
                          GPS_OUT_REF(int) steps) {
  scale = 1.0;
  steps = 0;
  int n = extraordinary_halvings(GPS_MAX(s, t));  // both below ½ exactly while max(s, t) is
  if (n < 0) return -1;
  s = GPS_LDEXP(s, n);
  t = GPS_LDEXP(t, n);
  int child = s >= 0.5 ? (t >= 0.5 ? 2 : 1) : 3;
  s = s >= 0.5 ? 2.0 * s - 1.0 : 2.0 * s;
  t = t >= 0.5 ? 2.0 * t - 1.0 : 2.0 * t;
  scale = 2.0 * GPS_LDEXP(GPS_REAL(1.0), n);
  return extraordinary_block(n, child, steps);
}

#ifndef GPS_GLSL
}  // namespace gps
#endif
