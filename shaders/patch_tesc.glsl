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
  vec2 inner = quad_inner_levels(level);  // tess_levels.glsl
  gl_TessLevelInner[0] = inner[0];
  gl_TessLevelInner[1] = inner[1];
}
