// A round dot of one colour, its rim faded over about a pixel so that it is drawn smooth.
uniform vec4 u_colour;
uniform float u_diameter;
layout(location = 0) out vec4 out_color;
void main() {
  const float r = length(2.0 * gl_PointCoord - 1.0) * 0.5 * u_diameter;  // pixels from the centre
  const float coverage = clamp(0.5 * u_diameter - r + 0.5, 0.0, 1.0);
  if (coverage <= 0.0) discard;
  out_color = vec4(u_colour.rgb, u_colour.a * coverage);
}
