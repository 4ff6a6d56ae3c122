#pragma once
// The surface point under a pixel, read back from the position AOV (the GL part of picking; rays,
// projection and vertex/ellipsoid picking are GL-free, in view/).
#include <glm/glm.hpp>
#include <optional>

#include "render/gl/render_target.h"

namespace gps {

/// The world position of the limit surface under a pixel (window coordinates) of the last draw into
/// `target`, read from its position AOV; nullopt where the pixel shows background.
std::optional<glm::vec3> surface_point(const RenderTarget& target, glm::vec2 pixel);

}  // namespace gps
