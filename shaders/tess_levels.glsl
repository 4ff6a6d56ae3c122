// Tessellation levels: uniform, or adaptive from the projected size of each patch edge, computed
// from points that both patches beside it read alike (no cracks): its mesh edge's two end points,
// and the limit points at its ends and halfway along it that the corner pass keeps
// (corner_limit_comp.glsl). The tessellation control stages and the surface cache's level check
// (shaders/patch_level_check_comp.glsl) both take a patch's outer levels from here; `precise` keeps
// them alike in both stages. Follows canonical_edge.glsl; preceded by `#define
// GPS_TRIANGLE_PATCHES` for Loop's triangle patches.
uniform mat4 u_view_projection;
uniform vec2 u_viewport;
uniform float u_level;        // uniform level, when u_pixels <= 0
uniform float u_pixels;       // adaptive: target edge length in pixels
uniform int u_debug_mismatch; // tests only: break edge agreement on purpose
uniform int u_first_patch;    // patches are drawn in batches; gl_PrimitiveID restarts with each
layout(std430, binding = kBindingCornerLimits) readonly buffer CornerLimits { vec4 corner_limits[]; };
layout(std430, binding = kBindingCurveMidpoints) readonly buffer CurveMidpoints { vec4 curve_midpoints[]; };

#ifdef GPS_TRIANGLE_PATCHES
const int kLevelCorners = 3;
#else
const int kLevelCorners = 4;
#endif

// A segment's size on screen: the projected diameter in pixels of the sphere centred at its midpoint
// whose diameter is its length (OpenSubdiv's measure). The projected length would vanish for a
// segment seen end-on, and give level 1 to the patches whose silhouette runs along it. A diameter d
// at clip depth w spans d·|row|/w of normalised device coordinates, `row` the view-projection's x or
// y row (a projection of a rigid view, scaled: both rows have the one scale for square pixels).
// Negative where an end is behind the eye.
float segment_pixels(vec3 first, vec3 second) {
  mat4 rows = transpose(u_view_projection);
  precise float w_first = dot(rows[3], vec4(first, 1.0));
  precise float w_second = dot(rows[3], vec4(second, 1.0));
  if (w_first <= 0.0 || w_second <= 0.0) return -1.0;
  precise float scale = 0.5 * max(length(rows[0].xyz) * u_viewport.x, length(rows[1].xyz) * u_viewport.y);
  precise float pixels = distance(first, second) * scale / (0.5 * (w_first + w_second));
  return pixels;
}

// The size on screen of a mesh edge's chord between its end points a and b, taken in index order so
// that both patches beside the edge compute the same (surface_cache.cpp's hysteresis measures
// edges alike); negative where an end is behind the eye.
float chord_pixels(int a, int b) { return segment_pixels(point_mean(min(a, b)), point_mean(max(a, b))); }

// The limit point at corner c of patch p, from its owner's slot.
vec3 corner_limit(int p, int c) {
  int o = 2 * (kLevelCorners * p + c);
  return corner_limits[2 * (kLevelCorners * corner_owners[o] + (corner_owners[o + 1] & kOwnerCornerMask))].xyz;
}

// The size on screen of the limit curve along edge k of patch p, the edge that names it for both
// sides (curve_edge): the sizes of its two halves, each a sphere's as the chord's, from the limit
// points at its ends and its midpoint; negative where one is behind the eye. Where flat Gaussians
// bend the curve far from the chord, the chord alone gives too few segments.
float curve_pixels(int p, int k) {
  vec3 first = corner_limit(p, k), second = corner_limit(p, (k + 1) % kLevelCorners);
  vec3 middle = curve_midpoints[kLevelCorners * p + k].xyz;
  float first_half = segment_pixels(first, middle), second_half = segment_pixels(middle, second);
  if (first_half < 0.0 || second_half < 0.0) return -1.0;
  precise float pixels = first_half + second_half;
  return pixels;
}

// The level of the mesh edge that edge k of patch p lies on, from the end points a and b of its chord
// and its limit curve (curve_edge; `part` the patch edge's PatchEdgePart): the larger size on
// screen over the target, rounded up, clamped to 1–64; an edge with a point behind the eye gets 64.
// Where the curve measured is a half's own (a half beside a half, or on the boundary), the mesh
// edge's curve counts twice its size.
float edge_level(int a, int b, int p, int k, int part) {
  if (u_pixels <= 0.0) return u_level;
  float chord = chord_pixels(a, b);
  ivec2 curve = curve_edge(p, k, part, kLevelCorners);
  bool half_curve = part != kEdgeWhole && part != kEdgeWholeBesideHalves &&
                    patch_edges[kPatchEdgeStride * curve.x + kPatchEdgeInts * curve.y + 2] != kEdgeWholeBesideHalves;
  precise float along = half_curve ? 2.0 * curve_pixels(curve.x, curve.y) : curve_pixels(curve.x, curve.y);
  if (chord < 0.0 || along < 0.0) return 64.0;
  return clamp(ceil(max(chord, along) / u_pixels), 1.0, 64.0);
}

// Quad patches. An edge met by two half-size patches gets an even level, each half half of it, so
// both sides place their vertices at the same points of the edge. Uniform level L is L segments
// along an edge of the mesh: a half-size patch takes L/2 on each of its edges and a quad's edge
// beside two of them L; for an odd L, one more: the halves take (L + 1)/2 and the quad's edge
// L + 1. Adaptive: the level of a half comes from the whole edge.
float patch_edge_level(int p, int k, bool half_size) {
  int e = kPatchEdgeStride * p + kPatchEdgeInts * k, part = patch_edges[e + 2];
  float level = ceil(u_level);
  float whole_beside_halves = level + mod(level, 2.0);
  if (u_pixels <= 0.0 && part == kEdgeWhole) return half_size ? 0.5 * whole_beside_halves : u_level;
  float whole = u_pixels <= 0.0 ? whole_beside_halves : edge_level(patch_edges[e], patch_edges[e + 1], p, k, part);
  if (part == kEdgeWhole) return whole;
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
  vec3 level;
  for (int k = 0; k < 3; ++k)
    level[k] = edge_level(corner_points[3 * p + k], corner_points[3 * p + (k + 1) % 3], p, k, kEdgeWhole);
  if (u_debug_mismatch != 0 && p % 2 == 0) level[0] = min(64.0, 2.0 * level[0] + 1.0);
  return level;
}

// Inner levels from a quad patch's outer ones: adaptive, the finer of the opposite edges; uniform,
// the patch's own grid (the coarser: they differ only where a quad's edge of L + 1 at an odd L meets
// two half-size patches, and that edge joins the L×L grid through the transition ring).
vec2 quad_inner_levels(vec4 level) {
  bool uniform_levels = u_pixels <= 0.0;
  return uniform_levels ? min(level.xy, level.zw) : max(level.xy, level.zw);
}

// A triangle patch's inner level: its finest edge's.
float triangle_inner_level(vec3 level) { return max(level[0], max(level[1], level[2])); }
