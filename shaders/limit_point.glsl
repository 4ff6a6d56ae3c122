// The limit point, its normal and plan node kind at (u, v) of a patch, or at the patch's corner
// `corner` (>= 0) from the corner's owner's limit (corner_limit_comp.glsl): what the tessellation
// stage (limit_point_tese.glsl) and the surface cache's evaluation after an edit
// (stored_vertex_evaluation_comp.glsl) compute alike, bit for bit. The including shader defines
// kCorners and evaluate_limit(), after canonical_edge.glsl.
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

// On an infinitely sharp crease of boundary point e's patch (sharp_boundary_point), where each
// side has its own normal: replaces the normal that limit_point() gave at e's canonical point c by
// that of e's own patch, evaluated there on an edge, at a corner from the corner pass's slot of its
// own; and `evaluated`, what the surface cache keeps to evaluate the point again, by e itself as
// −(patch + 1), 4·i + edge and n, which no two sides share. The position stays c's, bit for bit
// alike on every side.
void own_crease_normal(EdgePoint e, EdgePoint c, inout vec3 normal, out vec3 evaluated) {
  evaluated = vec3(-float(e.patch_id + 1), float(4 * e.i + e.edge), float(e.n));
  int corner = edge_point_corner(e, kCorners);
  if (corner >= 0) {
    normal = corner_limits[2 * (kCorners * e.patch_id + corner) + 1].xyz;
  } else if (c.patch_id != e.patch_id || c.edge != e.edge) {
    vec3 mu, mu_u, mu_v;
    int kind;
    evaluate_limit(e.patch_id, edge_point_uv(e, kCorners), mu, mu_u, mu_v, kind);
    normal = normalize(cross(mu_u, mu_v));
  }
}

// The edge point a crease's `evaluated` (own_crease_normal) names, or false for any other.
bool crease_edge_point(vec3 evaluated, out EdgePoint e) {
  if (evaluated.x >= 0.0) return false;
  int code = int(evaluated.y);
  e = EdgePoint(-int(evaluated.x) - 1, code & 3, code >> 2, int(evaluated.z));
  return true;
}
