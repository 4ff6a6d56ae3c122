// MatCap shading (thesis 4.1), normals as colours, or flat; plus world-space AOVs.
in vec3 v_position;
in vec3 v_normal;
in vec3 v_grid;  // wireframe: lines where a component is a whole number (tess_levels, mesh_geom)
flat in int v_kind;

uniform int u_mode;  // 0 MatCap, 1 normals, 2 flat
uniform mat4 u_view;
uniform sampler2D u_matcap;
uniform vec4 u_wire_color;  // alpha 0: no tessellation wireframe
uniform int u_flag_back_faces;  // crack checks: back faces in pure magenta
// The drawn points' frame (render/gl/normalised_frame.h): world = centre + unit · rotation · point.
uniform vec3 u_frame_centre;
uniform float u_frame_unit;
uniform mat3 u_frame_rotation;

layout(location = 0) out vec4 out_color;
layout(location = 1) out vec4 out_position;
layout(location = 2) out vec4 out_normal;

void main() {
  vec3 n = normalize(v_normal);
  if (u_mode == 2) n = normalize(cross(dFdx(v_position), dFdy(v_position)));
  n = u_frame_rotation * n;  // in the world
  vec3 shading_normal = gl_FrontFacing ? n : -n;
  vec3 view_normal = normalize(mat3(u_view) * shading_normal);
  vec3 color;
  if (u_mode == 1) color = 0.5 * n + 0.5;
  else color = texture(u_matcap, 0.5 * view_normal.xy + 0.5).rgb;
  // Tessellation wireframe: distance to the nearest grid line, in pixels. A uniform branch: without
  // the wireframe, a fragment costs what the static-buffer floor's does (whose constant v_grid the
  // linker folds away).
  float wire = 0.0;
  if (u_wire_color.a > 0.0) {
    vec3 d = abs(fract(v_grid - 0.5) - 0.5) / max(fwidth(v_grid), vec3(1e-6));
    float to_line = min(d.x, min(d.y, d.z));
    wire = u_wire_color.a * (1.0 - clamp(to_line - 0.25, 0.0, 1.0));
  }
  out_color = vec4(mix(color, u_wire_color.rgb, wire), 1.0);
  if (u_flag_back_faces != 0 && !gl_FrontFacing) out_color = vec4(1.0, 0.0, 1.0, 1.0);
  out_position = vec4(u_frame_centre + u_frame_unit * (u_frame_rotation * v_position), 1.0);
  out_normal = vec4(n, 1.0 + float(v_kind));  // w: 1 static mesh, 2 regular node, 3 terminal node
}
