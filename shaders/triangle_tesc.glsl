// Triangle patches (Loop): the levels of the three edges (tess_levels.glsl). Tessellation
// coordinate (x, y, z) is the barycentric of corners 0, 1, 2; outer level k is the edge where its
// k-th coordinate is 0, the edge opposite corner k.
layout(vertices = 1) out;
patch out int tc_patch;

void main() {
  int p = u_first_patch + gl_PrimitiveID;
  tc_patch = p;
  vec3 level = triangle_edge_levels(p);  // edges 01, 12, 20
  gl_TessLevelOuter[0] = level[1];
  gl_TessLevelOuter[1] = level[2];
  gl_TessLevelOuter[2] = level[0];
  gl_TessLevelInner[0] = triangle_inner_level(level);
}
