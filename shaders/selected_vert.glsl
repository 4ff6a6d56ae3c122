// Selected faces and edges (render/overlays/selected_elements.h), read from texture buffers: each
// primitive's item holds its corners (local vertex numbers) and the faces whose facing decides
// whether it shows (−1 none, −2 always: a boundary edge).
uniform samplerBuffer u_positions;  // per vertex: xyz in the frame, 1
uniform samplerBuffer u_planes;     // per face: its normal n and −n·c (c its centroid), in the frame
uniform isamplerBuffer u_items;     // triangles: a, b, c, face; lines: a, b, face, face
uniform int u_corners;              // 3 for triangles, 2 for lines
uniform mat4 u_view_projection;
uniform vec4 u_eye;  // the eye in the frame, w = 1; a parallel view: towards the eye, w = 0
flat out int v_shown;

bool facing(int face) { return face == -2 || (face >= 0 && dot(texelFetch(u_planes, face), u_eye) > 0.0); }

void main() {
  const ivec4 item = texelFetch(u_items, gl_VertexID / u_corners);
  const int corner = gl_VertexID % u_corners;
  const int vertex = corner == 0 ? item.x : corner == 1 ? item.y : item.z;
  v_shown = (u_corners == 3 ? facing(item.w) : facing(item.z) || facing(item.w)) ? 1 : 0;
  gl_Position = u_view_projection * vec4(texelFetch(u_positions, vertex).xyz, 1.0);
}
