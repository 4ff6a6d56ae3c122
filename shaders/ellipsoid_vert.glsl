// Covariance ellipsoids (thesis Fig. 1.1): three unit circles per instance, mapped by μ + Σ^½ · k.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec4 a_column0;
layout(location = 2) in vec4 a_column1;
layout(location = 3) in vec4 a_column2;
layout(location = 4) in vec4 a_column3;
uniform mat4 u_view_projection;
uniform float u_sigma;  // k: the k-σ ellipsoid
void main() {
  mat4 transform = mat4(a_column0, a_column1, a_column2, a_column3);
  gl_Position = u_view_projection * transform * vec4(u_sigma * a_position, 1.0);
}
