#pragma once
// Picking for the editor without GL: the base vertex near the mouse, the ellipsoid under it.
#include <glm/glm.hpp>
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "view/camera.h"
#include "view/projection.h"

namespace gps {

/// The base vertex whose mean projects nearest to `pixel`, within `radius` pixels; of vertices
/// equally near (within half a pixel) the front-most. -1 when none is that near. `hidden` (per
/// vertex, 1: hidden) leaves vertices out.
int pick_vertex(const Camera& camera, int width, int height, glm::vec2 pixel, const CovarianceMesh& mesh, float radius,
                const std::vector<char>* hidden = nullptr);

/// The vertex whose k-sigma ellipsoid {x : (x−μ)ᵀΣ⁻¹(x−μ) = k²} the pixel's ray meets first
/// (nearest entry point in front of the eye), of every vertex or of `candidates`; −1 when the ray
/// misses them all.
int pick_ellipsoid(const Camera& camera, int width, int height, glm::vec2 pixel, const CovarianceMesh& mesh,
                   double k_sigma, const std::vector<int>* candidates = nullptr);

}  // namespace gps
