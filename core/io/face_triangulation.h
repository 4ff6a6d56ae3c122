#pragma once
// A mesh's faces cut into triangles for a file that holds only triangles (glTF): each inside its face,
// turning as it does, and with diagonals that put no third face on an edge when the file is read back.
#include <array>
#include <cstdint>
#include <span>
#include <unordered_set>
#include <vector>

#include "core/mesh/covariance_mesh.h"

namespace gps {

/// The diagonals made so far, each as (min << 32 | max) of its corners.
using Diagonals = std::unordered_set<uint64_t>;

/// Face `corners` of `mesh` (at `positions`, `normal` its Newell normal) cut into triangles appended to
/// `out`, each turning as the face does: by ear clipping in the plane normal to `normal`, each time the
/// first ear from where the last was cut (so that a convex face is fanned from its first corner) whose
/// diagonal is neither an edge of the mesh nor in `diagonals` (either would put a third face on an
/// edge, or a face on another, in the file), else the first ear. Where no ear is left (a face without
/// area, or one that twists out of its plane) the rest is fanned from its first corner whose diagonals
/// are such and whose triangles turn as the face does. The diagonals made are added to `diagonals`.
void triangulate_face(const CovarianceMesh& mesh, std::span<const int> corners, const std::vector<Vec3>& positions,
                      const Vec3& normal, Diagonals& diagonals, std::vector<std::array<int, 3>>& out);

}  // namespace gps
