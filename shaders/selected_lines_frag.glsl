// A selected edge or outline in its colour, its rim faded over about a pixel.
in float v_across;
uniform vec4 u_color;
uniform float u_width;
layout(location = 0) out vec4 out_color;
void main() {
  const float coverage = clamp(0.5 * u_width + 0.5 - abs(v_across), 0.0, 1.0);
  if (coverage <= 0.0) discard;
  out_color = vec4(u_color.rgb, u_color.a * coverage);
}
