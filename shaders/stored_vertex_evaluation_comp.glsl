// Evaluates the surface cache's welded vertices again after an edit (render/cache/stored_vertex_evaluation.h),
// as limit_point_tese.glsl evaluated them when they were captured: at the patch and (u, v) it
// evaluated (the canonical patch on a patch edge, so that both sides stay bit for bit alike), a
// patch corner from its owner's limit point, a point on an infinitely sharp crease from the edge
// point it keeps (limit_point.glsl, own_crease_normal); position and normal · 2^kind, the grid kept.
// Preceded by `#define GPS_TRIANGLE_PATCHES` for Loop's triangle patches.
// One indirect dispatch for all listed blocks, their welded vertices one after the other: an invocation
// finds its block by the blocks' first invocations (shaders/evaluation_groups_comp.glsl).
layout(local_size_x = kWorkGroupSize) in;
layout(std430, binding = kBindingWeldedVertices) buffer WeldedVertices { float welded[]; };                  // 6 floats a vertex
layout(std430, binding = kBindingWeldedParameters) readonly buffer WeldedParameters { float parameters[]; };  // patch, u, v
layout(std430, binding = kBindingEvaluationBlocks) readonly buffer EvaluationBlocks { int blocks[]; };  // block, first vertex, bound
layout(std430, binding = kBindingEvaluationGroups) readonly buffer EvaluationGroups { uint groups[]; };  // dispatch, then first invocations
uniform int u_blocks;

// The corner whose (u, v) the tessellation stages' edge_point_uv gives, or −1: a boundary point
// evaluated at a patch's corner is that corner, any other is not.
#ifdef GPS_TRIANGLE_PATCHES
const int kCorners = 3;
int corner_at(vec2 uv) { return uv == vec2(0.0) ? 0 : uv == vec2(1.0, 0.0) ? 1 : uv == vec2(0.0, 1.0) ? 2 : -1; }
void evaluate_limit(int patch_id, vec2 uv, out vec3 mu, out vec3 mu_u, out vec3 mu_v, out int kind) {
  evaluate_triangle_plan(patch_id, uv.x, uv.y, mu, mu_u, mu_v, kind);
}
#else
const int kCorners = 4;
int corner_at(vec2 uv) {
  return uv == vec2(0.0) ? 0 : uv == vec2(1.0, 0.0) ? 1 : uv == vec2(1.0) ? 2 : uv == vec2(0.0, 1.0) ? 3 : -1;
}
void evaluate_limit(int patch_id, vec2 uv, out vec3 mu, out vec3 mu_u, out vec3 mu_v, out int kind) {
  evaluate_plan(patch_id, uv, mu, mu_u, mu_v, kind);
}
#endif
#include "shaders/limit_point.glsl"

void main() {
  uint invocation = gl_GlobalInvocationID.x;
  if (invocation >= groups[3 + u_blocks]) return;
  int low = 0, high = u_blocks - 1;  // the last listed block whose first invocation is at or before this one
  while (low < high) {
    int middle = (low + high + 1) / 2;
    if (groups[3 + middle] <= invocation) low = middle;
    else high = middle - 1;
  }
  uint v = uint(blocks[3 * low + 1]) + (invocation - groups[3 + low]);
  vec3 evaluated = vec3(parameters[3u * v], parameters[3u * v + 1u], parameters[3u * v + 2u]);
  int patch_id = int(evaluated.x);
  vec2 uv = evaluated.yz;
  int corner = corner_at(uv);
  EdgePoint e, c;
  bool crease = crease_edge_point(evaluated, e);
  if (crease) {  // as limit_point_tese.glsl evaluates it
    c = canonical_boundary_point(e, kCorners);
    patch_id = c.patch_id;
    uv = edge_point_uv(c, kCorners);
    corner = c.i == 0 ? c.edge : -1;
  }
  vec3 mu, normal;
  int kind;
  limit_point(patch_id, uv, corner, mu, normal, kind);
  if (crease) own_crease_normal(e, c, normal, evaluated);
  vec3 stored_normal = ldexp(normal, ivec3(kind));
  for (uint k = 0u; k < 3u; ++k) {
    welded[6u * v + k] = mu[k];
    welded[6u * v + 3u + k] = stored_normal[k];
  }
}
