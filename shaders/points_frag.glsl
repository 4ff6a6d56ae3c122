// A round point in its ramp colour (grey until the distances are measured), with a dark rim that
// keeps it apart from the surface and its neighbours.
in float v_ramp;
uniform sampler1D u_ramp;
uniform int u_ramp_texels;
uniform int u_measured;
layout(location = 0) out vec4 out_color;
void main() {
  const vec2 c = 2.0 * gl_PointCoord - 1.0;
  const float r2 = dot(c, c);
  if (r2 > 1.0) discard;
  const float n = float(u_ramp_texels);
  const vec3 colour = u_measured != 0 ? texture(u_ramp, (0.5 + v_ramp * (n - 1.0)) / n).rgb : vec3(0.86);
  out_color = vec4(mix(colour, 0.3 * colour, smoothstep(0.5, 0.9, r2)), 1.0);
}
