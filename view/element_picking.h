#pragma once
// Picking edges and faces of the control mesh under the mouse, without GL (the editor's edge and
// face selection modes).
#include <array>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh/covariance_mesh.h"
#include "view/projection.h"

namespace gps {

/// The edge {a, b} (a < b) whose projected segment passes nearest to `pixel`'s centre, within
/// `radius` pixels; of edges equally near (within half a pixel) the front-most at their nearest
/// point. nullopt when none is that near. `hidden` (per edge index, 1: hidden) leaves edges out.
std::optional<std::array<int, 2>> pick_edge(const Viewport& view, glm::vec2 pixel, const CovarianceMesh& mesh,
                                            float radius, const std::vector<char>* hidden = nullptr);

/// The face whose projected polygon (fanned into triangles from its first corner) contains
/// `pixel`'s centre, the nearest in depth of those that do; −1 when none does. `hidden` (per face,
/// 1: hidden) leaves faces out.
int pick_face(const Viewport& view, glm::vec2 pixel, const CovarianceMesh& mesh,
              const std::vector<char>* hidden = nullptr);

}  // namespace gps
