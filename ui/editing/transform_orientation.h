#pragma once
// Blender's transform orientations for the axis constraints of G / S / R: Global (the world axes)
// and Normal (a frame that follows the selection's surface). Local is the same as Global here, the
// document holding one object with no transform of its own, so it is left out.
#include <array>
#include <vector>

#include "core/mesh/covariance_mesh.h"

namespace gps {

enum class TransformOrientation { global, normal };
/// "global", "normal".
const char* orientation_name(TransformOrientation orientation);

/// The Normal orientation of a selection of vertices as Blender's edit mode makes it: its columns are
/// the frame's x, y, z, with z the normal and y a tangent. Where the selection holds whole faces, z is
/// the area-weighted average of their normals (Newell's sums); otherwise the average of the selected
/// vertices' normals (each the area-weighted normal of the faces around it). y is the longest edge
/// with both ends selected, projected into the plane normal to z (for one vertex: its longest edge),
/// and x = y × z. An empty selection, or one whose normal cancels out, gives the identity (Global).
Mat3 normal_frame(const CovarianceMesh& mesh, const std::vector<int>& vertices);
/// The same where the selection holds its own faces and edges (face and edge modes): `faces` stand for
/// the whole faces among the vertices and `edges` for the edges with both ends selected.
Mat3 normal_frame(const CovarianceMesh& mesh, const std::vector<int>& vertices, const std::vector<int>& faces,
                  const std::vector<std::array<int, 2>>& edges);

}  // namespace gps
