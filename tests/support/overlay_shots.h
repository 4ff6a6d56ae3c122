#pragma once
// An overlay's tests: a surface drawn into a target, read back before and after the overlay is drawn
// over it, and a pixel's colour.
#include <glm/glm.hpp>

#include "render/gl/render_target.h"
#include "render/image/image_io.h"
#include "render/pipeline/surface_renderer.h"
#include "view/camera.h"

namespace gps::test {

/// The red, green and blue of pixel (x, y).
inline glm::vec3 rgb_at(const Image& image, int x, int y) {
  return {image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2)};
}
inline glm::vec3 rgb_at(const Image& image, glm::vec2 p) { return rgb_at(image, int(p.x), int(p.y)); }

struct OverlayShot {
  Image plain, over;  // the surface alone, then with the overlay drawn over it
};

/// `renderer`'s surface under `camera` into a size × size target (level 8), then draw(target) over it.
template <class Draw>
OverlayShot shoot_over(SurfaceRenderer& renderer, const Camera& camera, int size, Draw&& draw) {
  RenderTarget target(size, size);
  DrawOptions o;
  o.level = 8;
  renderer.draw(target, camera, o);
  OverlayShot shot;
  shot.plain = target.read(0);
  draw(target);
  shot.over = target.read(0);
  return shot;
}

}  // namespace gps::test
