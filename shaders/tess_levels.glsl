// Tessellation levels: uniform, or adaptive from the projected length of each patch edge, computed
// from that edge's two corner points alone so that both patches beside it agree (no cracks).
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
