#include "render/gl/draw_options.h"

namespace gps {

namespace {

// Points `kept` to `copy`, holding what `list` points to, or to nothing where `list` is unset.
template <class T>
void keep_list(const std::vector<T>* list, std::vector<T>& copy, const std::vector<T>*& kept) {
  if (list) copy = *list;
  kept = list ? &copy : nullptr;
}

// Whether `list` is set where `kept` is and holds the same; then `list` stands for `kept` in `o`.
template <class T>
bool same_list(const std::vector<T>* list, const std::vector<T>* kept, const std::vector<T>*& in_o) {
  if ((list == nullptr) != (kept == nullptr) || (list && *list != *kept)) return false;
  in_o = kept;
  return true;
}

}  // namespace

void DrawnOptions::record(const DrawOptions& o) {
  values_ = o;
  keep_list(o.ellipsoid_vertices, ellipsoid_vertices_, values_.ellipsoid_vertices);
  keep_list(o.hidden_patches, hidden_patches_, values_.hidden_patches);
  keep_list(o.hidden_edges, hidden_edges_, values_.hidden_edges);
}

bool DrawnOptions::same(const DrawOptions& o) const {
  DrawOptions compared = o;
  return same_list(o.ellipsoid_vertices, values_.ellipsoid_vertices, compared.ellipsoid_vertices) &&
         same_list(o.hidden_patches, values_.hidden_patches, compared.hidden_patches) &&
         same_list(o.hidden_edges, values_.hidden_edges, compared.hidden_edges) && compared == values_;
}

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
  p.set("u_frame_rotation", glm::mat3(frame.rotation));
  p.set("u_view", glm::mat4(camera.view_double()));
  p.set("u_flag_back_faces", o.diagnostics.back_faces_magenta ? 1 : 0);
  p.set("u_mode", int(o.mode));
  p.set("u_matcap", 0);
  p.set("u_wire_color", glm::vec4(0.1f, 0.1f, 0.15f, o.wireframe ? 0.85f : 0.0f));
}

}  // namespace gps
