// The limit point, normal and plan node kind at every patch corner, evaluated once per compute pass
// by the corner's owner (core/plans/patch_adjacency.h) and read by every tessellation vertex there
// (limit_point_tese.glsl). A corner at an extraordinary vertex is its exact node's limit masks over
// K points: evaluated in the tessellation stage, the SIMD batch around it would run that and the
// regular leaf both. A corner on an infinitely sharp crease (kOwnerSharpCorner) is evaluated by its
// own patch too, whose normal there the patch's vertices at the corner take (limit_point.glsl).
// Preceded by `#define GPS_TRIANGLE_PATCHES` for Loop's triangle patches.
#include "shaders/compute_pass.glsl"
layout(std430, binding = kBindingCornerOwners) readonly buffer CornerOwners { int corner_owners[]; };
layout(std430, binding = kBindingCornerLimits) writeonly buffer CornerLimits { vec4 corner_limits[]; };
layout(std430, binding = kBindingCornerList) readonly buffer CornerList { int corner_list[]; };

#ifdef GPS_TRIANGLE_PATCHES
const int kCorners = 3;
#else
const int kCorners = 4;
#endif

void main() {
  int i = compute_invocation();
  if (i < 0) return;
  int slot = u_use_list != 0 ? corner_list[i] : i;  // kCorners · patch + corner
  int patch_id = slot / kCorners, corner = slot - kCorners * patch_id;
  int owner_corner = corner_owners[2 * slot + 1];
  bool owner = corner_owners[2 * slot] == patch_id && (owner_corner & kOwnerCornerMask) == corner;
  if (!owner && (owner_corner & kOwnerSharpCorner) == 0) return;  // its owner's slot holds it
  vec3 mu, mu_u, mu_v;
  int kind;
  // The corner's parameters as the tessellation stages' edge_point_uv gives them.
#ifdef GPS_TRIANGLE_PATCHES
  vec2 uv = corner == 0 ? vec2(0.0) : corner == 1 ? vec2(1.0, 0.0) : vec2(0.0, 1.0);
  evaluate_triangle_plan(patch_id, uv.x, uv.y, mu, mu_u, mu_v, kind);
#else
  vec2 uv = vec2(corner == 1 || corner == 2 ? 1.0 : 0.0, corner >= 2 ? 1.0 : 0.0);
  evaluate_plan(patch_id, uv, mu, mu_u, mu_v, kind);
#endif
  corner_limits[2 * slot] = vec4(mu, float(kind));
  corner_limits[2 * slot + 1] = vec4(normalize(cross(mu_u, mu_v)), 0.0);
}
