#include "render/overlays/point_overlay.h"

#include <glad/gl.h>

#include <algorithm>

#include "core/support/error.h"
#include "render/gl/gl_context.h"
#include "render/overlays/distance_ramp.h"
#include "render/gl/draw_options.h"
#include "shaders/embedded_shaders.h"

namespace gps {

namespace {
constexpr int kRampTexels = 256;
}  // namespace

PointOverlay::PointOverlay()
    : program_("points", {{GL_VERTEX_SHADER, {shaders::points_vert}}, {GL_FRAGMENT_SHADER, {shaders::points_frag}}}),
      ramp_(GL_TEXTURE_1D) {
  glVertexArrayVertexBuffer(vao_, 0, positions_, 0, 3 * sizeof(float));
  glEnableVertexArrayAttrib(vao_, 0);
  glVertexArrayAttribFormat(vao_, 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao_, 0, 0);
  glVertexArrayVertexBuffer(vao_, 1, distances_, 0, sizeof(float));
  glEnableVertexArrayAttrib(vao_, 1);
  glVertexArrayAttribFormat(vao_, 1, 1, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao_, 1, 1);
  std::vector<float> ramp(3 * kRampTexels);
  for (int i = 0; i < kRampTexels; ++i) {
    const glm::vec3 c = ramp_colour(float(i) / float(kRampTexels - 1));
    for (int k = 0; k < 3; ++k) ramp[3 * size_t(i) + size_t(k)] = c[k];
  }
  glTextureStorage1D(ramp_, 1, GL_RGBA8, kRampTexels);
  glTextureSubImage1D(ramp_, 0, 0, kRampTexels, GL_RGB, GL_FLOAT, ramp.data());
  glTextureParameteri(ramp_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(ramp_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(ramp_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  check_gl_errors("creating the point overlay");
}

void PointOverlay::upload_positions(const std::vector<Vec3>& points) {
  std::vector<float> framed(3 * points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const glm::dvec3 p = frame_.to_frame(glm::dvec3(points[i].x(), points[i].y(), points[i].z()));
    for (int k = 0; k < 3; ++k) framed[3 * i + size_t(k)] = float(p[k]);
  }
  glNamedBufferData(positions_, GLsizeiptr(std::max<size_t>(3, framed.size()) * sizeof(float)), framed.data(),
                    GL_STATIC_DRAW);
}

void PointOverlay::set_points(const std::vector<Vec3>& points, const NormalisedFrame& frame) {
  frame_ = frame;
  count_ = points.size();
  measured_ = false;
  upload_positions(points);
  const std::vector<float> unmeasured(std::max<size_t>(1, count_), 0.0f);
  glNamedBufferData(distances_, GLsizeiptr(unmeasured.size() * sizeof(float)), unmeasured.data(), GL_DYNAMIC_DRAW);
  check_gl_errors("uploading the target points");
}

void PointOverlay::set_frame(const std::vector<Vec3>& points, const NormalisedFrame& frame) {
  if (points.size() != count_) throw Error("the target points changed their count while moving to a new frame");
  frame_ = frame;
  upload_positions(points);
}

void PointOverlay::set_distances(const std::vector<float>& distances) {
  if (distances.size() != count_)
    throw Error("the target has " + std::to_string(count_) + " points but " + std::to_string(distances.size()) +
                " distances were measured");
  if (count_ > 0) glNamedBufferSubData(distances_, 0, GLsizeiptr(count_ * sizeof(float)), distances.data());
  measured_ = true;
}

void PointOverlay::draw(const RenderTarget& target, const Camera& camera, const Style& style) const {
  if (count_ == 0) return;
  const float aspect = float(target.width()) / float(target.height());
  program_.set("u_view_projection", frame_view_projection(camera, aspect, frame_));
  program_.set("u_eye", glm::vec3(frame_.to_frame(camera.eye_double())));
  program_.set("u_towards_eye", style.towards_eye);
  program_.set("u_point_size", style.point_size);
  program_.set("u_max_distance", float(style.max_distance > 0.0 ? style.max_distance : 1.0));
  program_.set("u_ramp", 0);
  program_.set("u_ramp_texels", kRampTexels);
  program_.set("u_measured", measured_ ? 1 : 0);
  program_.use();
  target.bind();
  target.set_colour_only(true);
  glBindTextureUnit(0, ramp_);
  glBindVertexArray(vao_);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glEnable(GL_PROGRAM_POINT_SIZE);
  glDrawArrays(GL_POINTS, 0, GLsizei(count_));
  glDisable(GL_PROGRAM_POINT_SIZE);
  glBindVertexArray(0);
  target.set_colour_only(false);
  check_gl_errors("drawing the target points");
}

}  // namespace gps
