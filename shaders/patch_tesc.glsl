// Quad patches: the levels of the four edges (tess_levels.glsl).
layout(vertices = 1) out;
patch out int tc_patch;

void main() {
  int p = u_first_patch + gl_PrimitiveID;
  tc_patch = p;
  vec4 level = quad_edge_levels(p);  // edge k runs from corner k to corner k+1
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
