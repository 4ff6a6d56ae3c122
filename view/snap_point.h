#pragma once
// Where a transform snaps to under the mouse, without GL: the nearest vertex, the nearest point of an
// edge, or the point of the face under the pointer (Blender's snapping to vertex, edge and face).
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh/covariance_mesh.h"
#include "view/projection.h"

namespace gps {

/// What snapping aims at: whole steps of the transform's own amount, or a mesh element.
enum class SnapTarget { increment, vertex, edge, face };
/// "increment", "vertex", "edge", "face".
const char* snap_target_name(SnapTarget target);

/// A point snapped to and the element it lies on ("vertex 7", "edge 3–4", "face 2"; numbered from 0
/// as the editor shows them).
struct SnapPoint {
  Vec3 point;
  std::string element;
};

/// The point of `target` (vertex, edge or face) under `pixel`: the vertex projected nearest within
/// `radius` pixels; the point of the edge whose image passes nearest within `radius` that is closest
/// to the pixel's ray; the first point where the ray meets a face (fanned from its first corner).
/// Elements that touch a vertex of `moving` are left out, so a selection never snaps to itself.
/// nullopt when nothing is near (and always for SnapTarget::increment).
std::optional<SnapPoint> find_snap_point(const CovarianceMesh& mesh, const Viewport& view, glm::vec2 pixel,
                                         SnapTarget target, const std::vector<int>& moving, float radius);

}  // namespace gps
