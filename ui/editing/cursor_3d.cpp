#include "ui/editing/cursor_3d.h"

#include <cmath>
#include <cstdio>

namespace gps {

std::string Cursor3D::place(const Vec3& at, const std::string& how) {
  point = at;
  placed = true;
  char where[160];
  std::snprintf(where, sizeof where, "3D cursor %s (%.4g, %.4g, %.4g)", how.c_str(), at.x(), at.y(), at.z());
  return where;
}

std::optional<Vec3> Cursor3D::at_its_depth(const Viewport& view, glm::vec2 pixel) const {
  const Ray ray = pixel_ray(view.camera, view.width, view.height, pixel);
  const Vec3 origin = to_vec(ray.origin), direction = to_vec(ray.direction);
  const Vec3 facing = (to_vec(view.camera.target) - to_vec(view.camera.eye_double())).normalized();
  const double along = direction.dot(facing);
  if (!(std::abs(along) > 1e-9)) return std::nullopt;
  return origin + direction * ((point - origin).dot(facing) / along);
}

}  // namespace gps
