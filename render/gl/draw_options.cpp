#include "render/gl/draw_options.h"

namespace gps {

void set_level_uniforms(const ShaderProgram& p, const glm::mat4& view_projection, glm::vec2 viewport,
                        const DrawOptions& o) {
  p.set("u_view_projection", view_projection);
  p.set("u_viewport", viewport);
  p.set("u_level", uniform_level(o));
  p.set("u_pixels", o.pixels);
  p.set("u_debug_mismatch", o.diagnostics.mismatched_edge_levels ? 1 : 0);
}

glm::mat4 frame_view_projection(const Camera& camera, float aspect, const NormalisedFrame& frame) {
  return glm::mat4(camera.view_projection_double(aspect) * frame.world_from_frame());
}

void set_frame_uniforms(const ShaderProgram& p, const Camera& camera, const DrawOptions& o, float aspect, int width,
                        int height, const NormalisedFrame& frame) {
  set_level_uniforms(p, frame_view_projection(camera, aspect, frame), glm::vec2(float(width), float(height)), o);
  p.set("u_frame_centre", glm::vec3(frame.centre));
  p.set("u_frame_unit", float(frame.unit));
  p.set("u_view", glm::mat4(camera.view_double()));
  p.set("u_flag_back_faces", o.diagnostics.back_faces_magenta ? 1 : 0);
  p.set("u_mode", int(o.mode));
  p.set("u_matcap", 0);
  p.set("u_wire_color", glm::vec4(0.1f, 0.1f, 0.15f, o.wireframe ? 0.85f : 0.0f));
}

}  // namespace gps
