// Tessellation levels: uniform, or adaptive from the projected size of each patch edge, computed
// from that edge's two corner points alone so that both patches beside it agree (no cracks). The
// tessellation control stages and the surface cache's level check (shaders/patch_level_check_comp.glsl)
// both take a patch's outer levels from here; `precise` keeps them alike in both stages.
uniform mat4 u_view_projection;
uniform vec2 u_viewport;
uniform float u_level;        // uniform level, when u_pixels <= 0
uniform float u_pixels;       // adaptive: target edge length in pixels
uniform int u_debug_mismatch; // tests only: break edge agreement on purpose
uniform int u_first_patch;    // patches are drawn in batches; gl_PrimitiveID restarts with each

// An edge's size on screen: the projected diameter in pixels of the sphere centred at its midpoint
// whose diameter is its length (OpenSubdiv's measure). The projected length would vanish for an edge
// seen end-on, and give level 1 to the patches whose silhouette runs along it. A diameter d at clip
// depth w spans d·|row|/w of normalised device coordinates, `row` the view-projection's x or y row
// (a projection of a rigid view, scaled: both rows have the one scale for square pixels). The ends
// are taken in index order so that both patches beside the edge compute the same level; an edge
// with an end behind the eye gets 64 (surface_cache.cpp's hysteresis measures edges alike).
float edge_level(int a, int b) {
  if (u_pixels <= 0.0) return u_level;
  precise vec3 first = point_mean(min(a, b));
  precise vec3 second = point_mean(max(a, b));
  mat4 rows = transpose(u_view_projection);
  precise float w_first = dot(rows[3], vec4(first, 1.0));
  precise float w_second = dot(rows[3], vec4(second, 1.0));
  if (w_first <= 0.0 || w_second <= 0.0) return 64.0;
  precise float scale = 0.5 * max(length(rows[0].xyz) * u_viewport.x, length(rows[1].xyz) * u_viewport.y);
  precise float pixels = distance(first, second) * scale / (0.5 * (w_first + w_second));
  return clamp(ceil(pixels / u_pixels), 1.0, 64.0);
}

// Quad patches. An edge met by two half-size patches gets an even level, each half half of it, so
// both sides place their vertices at the same points of the edge. Uniform level L is L segments
// along an edge of the mesh: a half-size patch takes L/2 on each of its edges and a quad's edge
// beside two of them L; for an odd L, one more: the halves take (L + 1)/2 and the quad's edge
// L + 1. Adaptive: the level of a half comes from the whole edge's two end points.
float patch_edge_level(int p, int k, bool half_size) {
  int e = kPatchEdgeStride * p + kPatchEdgeInts * k, part = patch_edges[e + 2];
  float level = ceil(u_level);
  float whole_beside_halves = level + mod(level, 2.0);
  if (part == kEdgeWhole) {
    if (u_pixels > 0.0 || !half_size) return edge_level(patch_edges[e], patch_edges[e + 1]);
    return 0.5 * whole_beside_halves;  // an inner edge of a split face
  }
  float whole = u_pixels <= 0.0 ? whole_beside_halves : edge_level(patch_edges[e], patch_edges[e + 1]);
  float half_level = ceil(0.5 * whole);
  return part == kEdgeWholeBesideHalves ? 2.0 * half_level : half_level;
}

// The levels of quad patch p's edges; edge k runs from corner k to corner k + 1.
vec4 quad_edge_levels(int p) {
  vec4 level;
  bool half_size = half_size_part(patch_edges[kPatchEdgeStride * p + 2]);
  for (int k = 0; k < 4; ++k) level[k] = patch_edge_level(p, k, half_size);
  if (u_debug_mismatch != 0 && p % 2 == 0) level[0] = min(64.0, 2.0 * level[0] + 1.0);
  return level;
}

// The levels of triangle patch p's edges from corner 0 to 1, 1 to 2 and 2 to 0.
vec3 triangle_edge_levels(int p) {
  int c0 = corner_points[3 * p], c1 = corner_points[3 * p + 1], c2 = corner_points[3 * p + 2];
  vec3 level = vec3(edge_level(c0, c1), edge_level(c1, c2), edge_level(c2, c0));
  if (u_debug_mismatch != 0 && p % 2 == 0) level[0] = min(64.0, 2.0 * level[0] + 1.0);
  return level;
}
