// The limit point, normal and plan node kind at every patch corner, evaluated once per compute pass
// by the corner's owner (core/plans/patch_adjacency.h) and read by every tessellation vertex there
// (limit_point_tese.glsl). A corner at an extraordinary vertex is its exact node's limit masks over
// K points: evaluated in the tessellation stage, the SIMD batch around it would run that and the
// regular leaf both. A corner on an infinitely sharp crease (kOwnerSharpCorner) is evaluated by its
// own patch too, whose normal there the patch's vertices at the corner take (limit_point.glsl).
// It also keeps the limit point halfway along each patch edge that names its edge's limit curve
// (canonical_edge.glsl, curve_edge), which the adaptive levels measure (tess_levels.glsl).
// Follows canonical_edge.glsl; preceded by `#define GPS_TRIANGLE_PATCHES` for Loop's triangle patches, and
// by `#define GPS_LEAVES_ONLY` in the program for the items of plans without an extraordinary node.
#include "shaders/compute_pass.glsl"
layout(std430, binding = kBindingCornerLimits) writeonly buffer CornerLimits { vec4 corner_limits[]; };
// Per corner slot: the limit point halfway along the edge that starts there, where that edge names its curve.
layout(std430, binding = kBindingCurveMidpoints) writeonly buffer CurveMidpoints { vec4 curve_midpoints[]; };
layout(std430, binding = kBindingCornerList) readonly buffer CornerList { int corner_items[]; };  // gpu_layout.h: kCornerItemOps
uniform int u_from;  // the list's first item of this program's (with GPS_LEAVES_ONLY, the leaves' are first)

#ifdef GPS_TRIANGLE_PATCHES
const int kCorners = 3;
#else
const int kCorners = 4;
#endif

// Tangents whose cross product is at most this much of their lengths' product run parallel: its
// direction is rounding alone. This and kFoldStep are the CPU's (core/evaluation/patch_eval.h).
const float kParallelSine = 1e-4;
bool parallel(vec3 mu_u, vec3 mu_v, vec3 n) {
  return !(dot(n, n) > kParallelSine * kParallelSine * dot(mu_u, mu_u) * dot(mu_v, mu_v));
}

// Where a corner's tangents run parallel the parametrisation folds there (a corner whose two edges
// run on in one line, as on a boundary edge split in two, whose new vertex is a corner of one face)
// and has no normal of its own: the normal a step of kFoldStep towards the patch's centre, which tends
// to the surface's normal there as the step shrinks; +z where the patch has none there either
// (collapsed to a curve or a point).
const float kFoldStep = 1.0 / 256.0;

// One evaluation per item. Which slot evaluates what (its owner a corner, the edge naming its curve a
// midpoint) the list's builder decides (render/pipeline/corner_limit_pass.h); it lists the evaluations
// first, and the slots that hold zero after them, which corner_clear_comp.glsl writes.
void main() {
  int i = compute_invocation();
  if (i < 0) return;
  int item = corner_items[u_from + i];
  int slot = item / kCornerItemOps, op = item - kCornerItemOps * slot;  // kCorners · patch + corner
  int patch_id = slot / kCorners, corner = slot - kCorners * patch_id;
  bool midpoint = op == kCornerItemMidpoint;
  // The corner's parameters as the tessellation stages' edge_point_uv gives them.
#ifdef GPS_TRIANGLE_PATCHES
  vec2 corner_uv = corner == 0 ? vec2(0.0) : corner == 1 ? vec2(1.0, 0.0) : vec2(0.0, 1.0);
#else
  vec2 corner_uv = vec2(corner == 1 || corner == 2 ? 1.0 : 0.0, corner >= 2 ? 1.0 : 0.0);
#endif
  vec2 uv = midpoint ? edge_point_uv(EdgePoint(patch_id, corner, 1, 2), kCorners) : corner_uv;
#ifdef GPS_TRIANGLE_PATCHES
  const vec2 centre = vec2(1.0 / 3.0);
#else
  const vec2 centre = vec2(0.5);
#endif
  // A second evaluation a step inside where a corner folds, in a loop the compiler keeps as one: a
  // second copy of the evaluation would cost every corner (registers, code) for the few that fold.
  vec3 limit = vec3(0.0), normal = vec3(0.0, 0.0, 1.0);
  int limit_kind = 0;
  for (int step = 0; step < 2; step += midpoint ? 2 : 1) {
    vec3 mu, mu_u, mu_v;
    int kind;
#ifdef GPS_TRIANGLE_PATCHES
    evaluate_triangle_plan(patch_id, uv.x, uv.y, mu, mu_u, mu_v, kind);
#else
    evaluate_plan(patch_id, uv, mu, mu_u, mu_v, kind);
#endif
    if (step == 0) {
      limit = mu;
      limit_kind = kind;
    }
    vec3 n = cross(mu_u, mu_v);
    if (!parallel(mu_u, mu_v, n)) {
      normal = normalize(n);
      break;
    }
    uv = mix(corner_uv, centre, kFoldStep);
  }
  if (midpoint) {
    curve_midpoints[slot] = vec4(limit, 0.0);
  } else {
    corner_limits[2 * slot] = vec4(limit, float(limit_kind));
    corner_limits[2 * slot + 1] = vec4(normal, 0.0);
  }
}
