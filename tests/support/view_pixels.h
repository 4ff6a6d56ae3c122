#pragma once
// Looking at a mesh in tests without a window: the view the editor frames it in at first, and the
// window pixel whose centre a point projects to (pixel_ray takes a pixel's centre, pixel + 0.5).
#include <glm/glm.hpp>

#include "view/camera.h"
#include "view/projection.h"

namespace gps::test {

/// `mesh` framed as the editor first frames it, in a width × height view.
inline Viewport framed_view(const CovarianceMesh& mesh, int width = 640, int height = 480) {
  Viewport v;
  v.camera = frame_mesh(mesh);
  v.width = width;
  v.height = height;
  return v;
}

/// The pixel whose centre `p` projects to; (−1, −1) behind the eye.
inline glm::vec2 pixel_of(const Viewport& v, const Vec3& p) {
  const auto q = project_to_pixel(v.camera, v.width, v.height, to_glm(p));
  return q ? glm::vec2(*q) - glm::vec2(0.5f) : glm::vec2(-1.0f);
}

}  // namespace gps::test
