// Quad patches: the levels of the four edges (tess_levels.glsl).
layout(vertices = 1) out;
patch out int tc_patch;

// An edge met by two half-size patches gets an even level, each half half of it, so both sides place
// their vertices at the same points of the edge. Uniform level L is L segments along an edge of the
// mesh: a half-size patch takes L/2 on each of its edges and a quad's edge beside two of them L; for
// an odd L the halves take L and the quad's edge 2L (at most 64). Adaptive: the level of a half
// comes from the whole edge's two end points.
float patch_edge_level(int p, int k, bool half_size) {
  int e = kPatchEdgeStride * p + kPatchEdgeInts * k, part = patch_edges[e + 2];
  float level = ceil(u_level);
  float whole_beside_halves = mod(level, 2.0) == 0.0 ? level : min(2.0 * level, 64.0);
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
  gl_TessLevelInner[0] = max(level[0], level[2]);
  gl_TessLevelInner[1] = max(level[1], level[3]);
}
