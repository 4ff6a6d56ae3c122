// The limit point, its normal and plan node kind at (u, v) of a patch, or at the patch's corner
// `corner` (>= 0) from the corner's owner's limit (corner_limit_comp.glsl): what the tessellation
// stage (limit_point_tese.glsl) and the surface cache's evaluation after an edit
// (stored_vertex_evaluation_comp.glsl) compute alike, bit for bit. The including shader defines
// kCorners and evaluate_limit().
layout(std430, binding = kBindingCornerLimits) readonly buffer CornerLimits { vec4 corner_limits[]; };

void limit_point(int patch_id, vec2 uv, int corner, out vec3 mu, out vec3 normal, out int kind) {
  if (corner >= 0) {
    int slot = kCorners * patch_id + corner;
    vec4 limit = corner_limits[2 * slot];
    mu = limit.xyz;
    kind = int(limit.w);
    normal = corner_limits[2 * slot + 1].xyz;
  } else {
    vec3 mu_u, mu_v;
    evaluate_limit(patch_id, uv, mu, mu_u, mu_v, kind);
    normal = normalize(cross(mu_u, mu_v));
  }
}
