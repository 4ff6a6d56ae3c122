#pragma once
// Cutting one face into pieces, for the operations that cut faces along a line (bisect, knife): a
// piece is a corner cycle in the face's orientation, split along a chain of vertices between two of
// its corners, and triangulated where the mesh must stay one of triangles.
#include <vector>

#include "core/mesh/linalg.h"

namespace gps {

/// Splits the one piece holding both ends of `cut` (its first and last vertex) along it, its inner
/// vertices becoming corners of both halves: the piece keeps the half from the first end to the last
/// along its own cycle, the other half is appended. False when no piece holds both ends apart (two
/// ends that are neighbours in the piece need inner vertices between them).
bool split_along(std::vector<std::vector<int>>& pieces, const std::vector<int>& cut);

/// Each piece of more than three corners cut into triangles by ear clipping in the plane normal to
/// `normal` (the face's orientation), the ear with the shortest diagonal first (a quad is split by its
/// shorter diagonal); corners on the straight line between their neighbours are left out of the
/// clipping and fanned into the triangle on their line, so that no triangle is without area where the
/// piece has any. The first triangle takes the piece's place, the others are appended.
void triangulate_pieces(std::vector<std::vector<int>>& pieces, const std::vector<Vec3>& means, const Vec3& normal);

}  // namespace gps
