// Target points over the surface (render/overlays/point_overlay.h): each moved a little towards the
// eye, so that one on the surface is not hidden by it, and given its place on the distance ramp.
layout(location = 0) in vec3 a_position;
layout(location = 1) in float a_distance;
uniform mat4 u_view_projection;
uniform vec3 u_eye;             // in the points' frame
uniform float u_towards_eye;    // frame units
uniform float u_point_size;     // pixels
uniform float u_max_distance;   // the ramp's end, in the distances' units
out float v_ramp;
void main() {
  const vec3 p = a_position + u_towards_eye * normalize(u_eye - a_position);
  gl_Position = u_view_projection * vec4(p, 1.0);
  gl_PointSize = u_point_size;
  v_ramp = clamp(a_distance / u_max_distance, 0.0, 1.0);
}
