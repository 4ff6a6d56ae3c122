// Quad patches: the levels of the four edges (tess_levels.glsl).
layout(vertices = 1) out;
patch out int tc_patch;

// An edge met by two half-size patches (core/plan_table.h, PatchEdgePart) gets an even level, each
// half half of it, so both sides place their vertices at the same points of the edge; the level of
// a half comes from the whole edge's two end points.
float patch_edge_level(int p, int k) {
  int e = kPatchEdgeStride * p + kPatchEdgeInts * k, part = patch_edges[e + 2];
  if (part == kEdgeWhole) return edge_level(patch_edges[e], patch_edges[e + 1]);
  float whole = u_pixels <= 0.0 ? min(2.0 * ceil(u_level), 64.0) : edge_level(patch_edges[e], patch_edges[e + 1]);
  float half_level = ceil(0.5 * whole);
  return part == kEdgeWholeBesideHalves ? 2.0 * half_level : half_level;
}

void main() {
  int p = u_first_patch + gl_PrimitiveID;
  tc_patch = p;
  float level[4];  // edge k runs from corner k to corner k+1
  for (int k = 0; k < 4; ++k) level[k] = patch_edge_level(p, k);
  if (u_debug_mismatch != 0 && p % 2 == 0) level[0] = min(64.0, 2.0 * level[0] + 1.0);
  gl_TessLevelOuter[0] = level[3];  // u = 0
  gl_TessLevelOuter[1] = level[0];  // v = 0
  gl_TessLevelOuter[2] = level[1];  // u = 1
  gl_TessLevelOuter[3] = level[2];  // v = 1
  gl_TessLevelInner[0] = max(level[0], level[2]);
  gl_TessLevelInner[1] = max(level[1], level[3]);
}
