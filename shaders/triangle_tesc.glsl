// Triangle patches (Loop): the levels of the three edges (tess_levels.glsl). Tessellation
// coordinate (x, y, z) is the barycentric of corners 0, 1, 2; outer level k is the edge where its
// k-th coordinate is 0, the edge opposite corner k.
layout(vertices = 1) out;
patch out int tc_patch;

void main() {
  int p = u_first_patch + gl_PrimitiveID;
  tc_patch = p;
  int c0 = corner_points[3 * p], c1 = corner_points[3 * p + 1], c2 = corner_points[3 * p + 2];
  float l01 = edge_level(c0, c1), l12 = edge_level(c1, c2), l20 = edge_level(c2, c0);
  if (u_debug_mismatch != 0 && p % 2 == 0) l01 = min(64.0, 2.0 * l01 + 1.0);
  gl_TessLevelOuter[0] = l12;
  gl_TessLevelOuter[1] = l20;
  gl_TessLevelOuter[2] = l01;
  gl_TessLevelInner[0] = max(l01, max(l12, l20));
}
