// Quad patches: the levels of the four edges (tess_levels.glsl).
layout(vertices = 1) out;
patch out int tc_patch;

void main() {
  int p = u_first_patch + gl_PrimitiveID;
  tc_patch = p;
  float level[4];  // edge k runs from corner k to corner k+1
  for (int k = 0; k < 4; ++k) level[k] = edge_level(corner_points[4 * p + k], corner_points[4 * p + (k + 1) % 4]);
  if (u_debug_mismatch != 0 && p % 2 == 0) level[0] = min(64.0, 2.0 * level[0] + 1.0);
  gl_TessLevelOuter[0] = level[3];  // u = 0
  gl_TessLevelOuter[1] = level[0];  // v = 0
  gl_TessLevelOuter[2] = level[1];  // u = 1
  gl_TessLevelOuter[3] = level[2];  // v = 1
  gl_TessLevelInner[0] = max(level[0], level[2]);
  gl_TessLevelInner[1] = max(level[1], level[3]);
}
