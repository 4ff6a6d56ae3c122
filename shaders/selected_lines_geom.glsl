// A selected edge or outline as a band u_width pixels wide (and a pixel more, faded, for a smooth
// rim), where it shows and both ends lie in front of the eye.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;
flat in int v_shown[];
uniform vec2 u_viewport;  // pixels
uniform float u_width;    // pixels
out float v_across;       // pixels from the line's middle

void main() {
  const vec4 a = gl_in[0].gl_Position, b = gl_in[1].gl_Position;
  if (v_shown[0] == 0 || a.w <= 0.0 || b.w <= 0.0) return;
  const vec2 half_viewport = 0.5 * u_viewport;
  vec2 along = (b.xy / b.w - a.xy / a.w) * half_viewport;
  if (dot(along, along) < 1e-12) along = vec2(1.0, 0.0);
  const float half_band = 0.5 * u_width + 1.0;
  const vec2 side = half_band * normalize(vec2(-along.y, along.x)) / half_viewport;  // in NDC
  for (int end = 0; end < 2; ++end)
    for (int s = 1; s >= -1; s -= 2) {
      const vec4 p = end == 0 ? a : b;
      gl_Position = p + vec4(float(s) * side * p.w, 0.0, 0.0);
      v_across = float(s) * half_band;
      EmitVertex();
    }
  EndPrimitive();
}
