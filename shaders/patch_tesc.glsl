// Tessellation levels: uniform, or adaptive from the projected length of each patch edge, computed
// from that edge's two corner points alone so that both patches beside it agree (no cracks).
layout(vertices = 1) out;
patch out int tc_patch;

uniform mat4 u_view_projection;
uniform vec2 u_viewport;
uniform float u_level;        // uniform level, when u_pixels <= 0
uniform float u_pixels;       // adaptive: target edge length in pixels
uniform int u_debug_mismatch; // tests only: break edge agreement on purpose
uniform int u_first_patch;    // patches are drawn in batches; gl_PrimitiveID restarts with each

float edge_level(int a, int b) {
  if (u_pixels <= 0.0) return u_level;
  vec4 pa = u_view_projection * vec4(point_mean(a), 1.0);
  vec4 pb = u_view_projection * vec4(point_mean(b), 1.0);
  if (pa.w <= 0.0 || pb.w <= 0.0) return 64.0;
  float pixels = length((pa.xy / pa.w - pb.xy / pb.w) * 0.5 * u_viewport);
  return clamp(ceil(pixels / u_pixels), 1.0, 64.0);
}

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
