#pragma once
// Between window pixels and the world: rays through pixels (inverse view-projection), points
// projected to pixels, the world size of a pixel, and the candidate projected nearest a pixel. All in
// double (the camera's view_projection_double): a mesh far from the origin, or of any scale, is
// picked and overlaid as it is at the origin at unit size.
#include <glm/glm.hpp>
#include <optional>

#include "core/mesh/linalg.h"
#include "view/camera.h"

namespace gps {

/// What a window shows: camera and window size in window pixels (the mouse's units).
struct Viewport {
  Camera camera;
  int width = 1, height = 1;
};

struct Ray {
  glm::dvec3 origin;
  glm::dvec3 direction;  // unit length
};

/// The ray from the eye through the centre of a pixel given in window coordinates (origin top-left,
/// y down, as windows report the mouse): the pixel's NDC point unprojected by (P·V)⁻¹.
Ray pixel_ray(const Camera& camera, int width, int height, glm::vec2 pixel);

/// The window pixel (origin top-left) of a world point and its NDC depth in z; nullopt behind the eye.
std::optional<glm::vec3> project_to_pixel(const Camera& camera, int width, int height, const Vec3& world);
inline std::optional<glm::vec3> project_to_pixel(const Camera& camera, int width, int height, const glm::vec3& world) {
  return project_to_pixel(camera, width, height, Vec3(world.x, world.y, world.z));
}

/// project_to_pixel() of a double-precision point, nullopt also outside the depth range [−1, 1].
std::optional<glm::vec3> visible_pixel(const Camera& camera, int width, int height, const Vec3& world);

/// World length of one window pixel at the depth of `point` (2·depth·tan(fov/2)/height).
double world_per_pixel(const Camera& camera, int height, const Vec3& point);

inline glm::vec3 to_glm(const Vec3& v) { return {float(v.x()), float(v.y()), float(v.z())}; }
inline Vec3 to_vec(const glm::vec3& v) { return {double(v.x), double(v.y), double(v.z)}; }
inline Vec3 to_vec(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

/// Finds, among candidates offered one by one, the one projected nearest to a pixel within a radius.
/// Candidates as near as the best (within `tolerance` pixels) win by a higher priority, then by
/// being in front. Used by vertex picking and by the handles.
class NearestProjected {
public:
  NearestProjected(const Camera& camera, int width, int height, glm::vec2 pixel, float radius, float tolerance);
  /// Offers candidate `id` at world point `point`.
  void consider(int id, const Vec3& point, int priority = 0);
  /// The best candidate so far; −1 when none was near enough.
  int best() const { return best_; }

private:
  const Camera& camera_;
  int width_, height_;
  glm::vec2 centre_;
  float radius_, tolerance_;
  int best_ = -1, best_priority_ = 0;
  float best_distance_, best_depth_ = 2.0f;
};

}  // namespace gps
