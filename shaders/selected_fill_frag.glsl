// A selected face's fill, where the face looks at the eye.
flat in int v_shown;
uniform vec4 u_color;
layout(location = 0) out vec4 out_color;
void main() {
  if (v_shown == 0) discard;
  out_color = u_color;
}
