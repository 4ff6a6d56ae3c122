// Vertex dots (render/overlays/vertex_dots.h): each vertex a point of the dot's size.
layout(location = 0) in vec3 a_position;
uniform mat4 u_view_projection;
uniform float u_diameter;  // pixels
void main() {
  gl_Position = u_view_projection * vec4(a_position, 1.0);
  gl_PointSize = u_diameter;
}
