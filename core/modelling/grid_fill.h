#pragma once
// Grid fill, as Blender's Face > Grid Fill does it: a hole's boundary loop of an even number of
// vertices closed by a grid of quads.
//
// Like every modelling operation (core/modelling/mesh_arrays.h) these take a mesh and return a new
// one with a selection and a one-line summary, never changing their input; on refusal they throw
// gps::Error with a one-line reason and nothing is changed.
#include <vector>

#include "core/modelling/mesh_arrays.h"

namespace gps {

/// Fills the boundary loop `loop` (its vertices in order, either way round; n even, at least 4) with
/// a grid of quads. The loop is cut into four sides as Blender cuts it: the first corner is the vertex
/// where the loop turns most (|π − its angle| largest, the first of equals), moved `offset` vertices
/// on along the loop; two opposite sides have `span` edges and the other two n/2 − span. Given as 0,
/// span is Blender's calculated one: the edges to the next vertex that turns more than the rest (not
/// the one opposite the first corner), else n/4. The grid's inner vertices lie on the discrete Coons
/// patch of the four sides (bilinearly blended, by grid index, the sum of the two ruled surfaces
/// between opposite sides less the bilinear surface of the corners); each takes the covariance of
/// the 9D blend of the four loop vertices its row and column end at, weighted as the two ruled
/// surfaces weight them. The quads run against the loop's faces; on a mesh of triangles they are split
/// into triangles. Refuses an odd or short loop, a vertex listed twice, a pair that is not a boundary
/// edge and a span that leaves no room (from 1 to n/2 − 1). Selection: the grid's vertices.
Modelled grid_fill(const CovarianceMesh& mesh, const std::vector<int>& loop, int span = 0, int offset = 0);

/// The editor's grid fill: the selected vertices must be one whole boundary loop, filled as grid_fill
/// fills it in its faces' order.
Modelled grid_fill_selected(const CovarianceMesh& mesh, const std::vector<int>& vertices, int span = 0, int offset = 0);

}  // namespace gps
