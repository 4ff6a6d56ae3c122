#pragma once
// Picking for the editor: rays through pixels (inverse view-projection), base vertices near the
// mouse, and the surface point under a pixel read back from the position AOV.
#include <glm/glm.hpp>
#include <optional>

#include "core/covariance_mesh.h"
#include "render/camera.h"
#include "render/render_target.h"

namespace gps {

struct Ray {
  glm::vec3 origin;
  glm::vec3 direction;  // unit length
};

/// The ray from the eye through the centre of a pixel given in window coordinates (origin top-left,
/// y down, as windows report the mouse): the pixel's NDC point unprojected by (P·V)⁻¹.
Ray pixel_ray(const Camera& camera, int width, int height, glm::vec2 pixel);

/// The window pixel (origin top-left) of a world point and its NDC depth in z; nullopt behind the eye.
std::optional<glm::vec3> project_to_pixel(const Camera& camera, int width, int height, const glm::vec3& world);

/// The base vertex whose mean projects nearest to `pixel`, within `radius` pixels; of vertices
/// equally near (within half a pixel) the front-most. -1 when none is that near.
int pick_vertex(const Camera& camera, int width, int height, glm::vec2 pixel, const CovarianceMesh& mesh, float radius);

/// The vertex whose k-sigma ellipsoid {x : (x−μ)ᵀΣ⁻¹(x−μ) = k²} the pixel's ray meets first
/// (nearest entry point in front of the eye); −1 when the ray misses them all.
int pick_ellipsoid(const Camera& camera, int width, int height, glm::vec2 pixel, const CovarianceMesh& mesh, double k_sigma);

/// The world position of the limit surface under a pixel (window coordinates) of the last draw into
/// `target`, read from its position AOV; nullopt where the pixel shows background.
std::optional<glm::vec3> surface_point(const RenderTarget& target, glm::vec2 pixel);

}  // namespace gps
