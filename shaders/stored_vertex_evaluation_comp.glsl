// Evaluates the surface cache's welded vertices again after an edit (render/stored_vertex_evaluation.h),
// as limit_point_tese.glsl evaluated them when they were captured: at the patch and (u, v) it
// evaluated (the canonical patch on a patch edge, so that both sides stay bit for bit alike), a
// patch corner from its owner's limit point; position and normal · 2^kind, the grid kept.
// Preceded by `#define GPS_TRIANGLE_PATCHES` for Loop's triangle patches.
#include "shaders/compute_pass.glsl"
layout(std430, binding = kBindingCornerLimits) readonly buffer CornerLimits { vec4 corner_limits[]; };
layout(std430, binding = kBindingWeldedVertices) buffer WeldedVertices { float welded[]; };                  // 9 floats a vertex
layout(std430, binding = kBindingWeldedParameters) readonly buffer WeldedParameters { float parameters[]; };  // patch, u, v
uniform int u_range_first;  // invocation i evaluates welded vertex u_range_first + i

#ifdef GPS_TRIANGLE_PATCHES
const int kCorners = 3;
// The corner whose (u, v) edge_point_uv gives, or −1.
int corner_at(vec2 uv) { return uv == vec2(0.0) ? 0 : uv == vec2(1.0, 0.0) ? 1 : uv == vec2(0.0, 1.0) ? 2 : -1; }
#else
const int kCorners = 4;
int corner_at(vec2 uv) {
  return uv == vec2(0.0) ? 0 : uv == vec2(1.0, 0.0) ? 1 : uv == vec2(1.0) ? 2 : uv == vec2(0.0, 1.0) ? 3 : -1;
}
#endif

void main() {
  int i = compute_invocation();
  if (i < 0) return;
  uint v = uint(u_range_first + i);
  if (floatBitsToUint(parameters[3u * v]) == ~0u) return;  // past the block's welded vertices
  int patch_id = int(parameters[3u * v]);
  vec2 uv = vec2(parameters[3u * v + 1u], parameters[3u * v + 2u]);
  vec3 mu, mu_u, mu_v, normal;
  int kind;
  int corner = corner_at(uv);
  if (corner >= 0) {
    int slot = kCorners * patch_id + corner;
    vec4 limit = corner_limits[2 * slot];
    mu = limit.xyz;
    kind = int(limit.w);
    normal = corner_limits[2 * slot + 1].xyz;
  } else {
#ifdef GPS_TRIANGLE_PATCHES
    evaluate_triangle_plan(patch_id, uv.x, uv.y, mu, mu_u, mu_v, kind);
#else
    evaluate_plan(patch_id, uv, mu, mu_u, mu_v, kind);
#endif
    normal = normalize(cross(mu_u, mu_v));
  }
  vec3 stored_normal = ldexp(normal, ivec3(kind));
  for (uint k = 0u; k < 3u; ++k) {
    welded[9u * v + k] = mu[k];
    welded[9u * v + 3u + k] = stored_normal[k];
  }
}
