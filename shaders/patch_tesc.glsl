// Quad patches: the levels of the four edges (tess_levels.glsl).
layout(vertices = 1) out;
patch out int tc_patch;

// An edge met by two half-size patches gets an even level, each half half of it, so both sides place
// their vertices at the same points of the edge. Uniform level L is L segments along an edge of the
// mesh: a half-size patch takes L/2 on each of its edges and a quad's edge beside two of them L; for
// an odd L, one more: the halves take (L + 1)/2 and the quad's edge L + 1. Adaptive: the level of a
// half comes from the whole edge's two end points.
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

void main() {
  int p = u_first_patch + gl_PrimitiveID;
  tc_patch = p;
  float level[4];  // edge k runs from corner k to corner k+1
  bool half_size = half_size_part(patch_edges[kPatchEdgeStride * p + 2]);
  for (int k = 0; k < 4; ++k) level[k] = patch_edge_level(p, k, half_size);
  if (u_debug_mismatch != 0 && p % 2 == 0) level[0] = min(64.0, 2.0 * level[0] + 1.0);
  gl_TessLevelOuter[0] = level[3];  // u = 0
  gl_TessLevelOuter[1] = level[0];  // v = 0
  gl_TessLevelOuter[2] = level[1];  // u = 1
  gl_TessLevelOuter[3] = level[2];  // v = 1
  // Inner levels: adaptive, the finer of the opposite edges; uniform, the patch's own grid (the
  // coarser: they differ only where a quad's edge of L + 1 at an odd L meets two half-size patches,
  // and that edge joins the L×L grid through the transition ring).
  bool uniform_levels = u_pixels <= 0.0;
  gl_TessLevelInner[0] = uniform_levels ? min(level[0], level[2]) : max(level[0], level[2]);
  gl_TessLevelInner[1] = uniform_levels ? min(level[1], level[3]) : max(level[1], level[3]);
}
