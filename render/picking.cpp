#include "render/picking.h"

#include <glad/gl.h>

#include <Eigen/Cholesky>
#include <cmath>
#include <limits>

#include "render/gl_context.h"

namespace gps {

namespace {

glm::vec2 pixel_to_ndc(int width, int height, glm::vec2 pixel) {
  return {2.0f * pixel.x / float(width) - 1.0f, 1.0f - 2.0f * pixel.y / float(height)};
}

}  // namespace

Ray pixel_ray(const Camera& camera, int width, int height, glm::vec2 pixel) {
  const glm::vec2 ndc = pixel_to_ndc(width, height, pixel + glm::vec2(0.5f));
  const glm::mat4 inverse = glm::inverse(camera.view_projection(float(width) / float(height)));
  const glm::vec4 near_point = inverse * glm::vec4(ndc, -1.0f, 1.0f), far_point = inverse * glm::vec4(ndc, 1.0f, 1.0f);
  const glm::vec3 a = glm::vec3(near_point) / near_point.w, b = glm::vec3(far_point) / far_point.w;
  return {camera.eye(), glm::normalize(b - a)};
}

std::optional<glm::vec3> project_to_pixel(const Camera& camera, int width, int height, const glm::vec3& world) {
  const glm::vec4 clip = camera.view_projection(float(width) / float(height)) * glm::vec4(world, 1.0f);
  if (clip.w <= 0.0f) return std::nullopt;
  const glm::vec3 ndc = glm::vec3(clip) / clip.w;
  return glm::vec3((ndc.x + 1.0f) * 0.5f * float(width), (1.0f - ndc.y) * 0.5f * float(height), ndc.z);
}

int pick_vertex(const Camera& camera, int width, int height, glm::vec2 pixel, const CovarianceMesh& mesh, float radius) {
  const glm::vec2 centre = pixel + glm::vec2(0.5f);
  int best = -1;
  float best_distance = radius, best_depth = 2.0f;
  for (size_t i = 0; i < mesh.n_vertices(); ++i) {
    const Vec3 m = mesh.mean(i);
    const auto p = project_to_pixel(camera, width, height, glm::vec3(float(m.x()), float(m.y()), float(m.z())));
    if (!p || p->z < -1.0f || p->z > 1.0f) continue;
    const float distance = glm::length(glm::vec2(*p) - centre);
    if (distance > radius) continue;
    const bool nearer = distance < best_distance - 0.5f;
    const bool as_near_in_front = distance <= best_distance + 0.5f && p->z < best_depth;
    if (best < 0 || nearer || as_near_in_front) {
      best = int(i);
      best_distance = distance;
      best_depth = p->z;
    }
  }
  return best;
}

int pick_ellipsoid(const Camera& camera, int width, int height, glm::vec2 pixel, const CovarianceMesh& mesh, double k_sigma) {
  const Ray ray = pixel_ray(camera, width, height, pixel);
  const Vec3 origin(ray.origin.x, ray.origin.y, ray.origin.z), d(ray.direction.x, ray.direction.y, ray.direction.z);
  int best = -1;
  double best_t = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < mesh.n_vertices(); ++i) {
    // |o + t·d|²_{Σ⁻¹} = k² with o = origin − μ: a t² + 2 b t + c = 0, Σ⁻¹ applied by an LDLᵀ solve.
    const Eigen::LDLT<Mat3> ldlt(mesh.covariance(i));
    const Vec3 o = origin - mesh.mean(i);
    const Vec3 inv_d = ldlt.solve(d), inv_o = ldlt.solve(o);
    const double a = d.dot(inv_d), b = o.dot(inv_d), c = o.dot(inv_o) - k_sigma * k_sigma;
    const double discriminant = b * b - a * c;
    if (!(a > 0) || !(discriminant >= 0)) continue;
    const double root = std::sqrt(discriminant);
    const double t = (-b - root) / a > 0 ? (-b - root) / a : (-b + root) / a;  // the eye may be inside
    if (t > 0 && t < best_t) best_t = t, best = int(i);
  }
  return best;
}

std::optional<glm::vec3> surface_point(const RenderTarget& target, glm::vec2 pixel) {
  const int x = int(std::floor(pixel.x)), y = int(std::floor(pixel.y));
  if (x < 0 || y < 0 || x >= target.width() || y >= target.height()) return std::nullopt;
  float value[4] = {0, 0, 0, 0};
  glNamedFramebufferReadBuffer(target.framebuffer(), GL_COLOR_ATTACHMENT1);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, target.framebuffer());
  glReadPixels(x, target.height() - 1 - y, 1, 1, GL_RGBA, GL_FLOAT, value);
  check_gl_errors("reading the position under a pixel");
  if (value[3] < 0.5f) return std::nullopt;
  return glm::vec3(value[0], value[1], value[2]);
}

}  // namespace gps
