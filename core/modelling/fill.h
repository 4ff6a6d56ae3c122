#pragma once
// Filling holes: a new face through boundary vertices, oriented like its neighbours.
//
// Like every modelling operation (core/modelling/mesh_arrays.h) these take a mesh and return a new
// one with a selection and a one-line summary, never changing their input; on refusal they throw
// gps::Error with a one-line reason and nothing is changed. The new face is appended; no vertex is
// added or moved.
#include <vector>

#include "core/modelling/mesh_arrays.h"

namespace gps {

/// A new face through the vertices (3 or more, distinct) in the given order, or reversed where that
/// is the orientation that agrees with the neighbouring faces: a new edge that is an existing boundary
/// edge runs opposite to it; with no such edge, the face follows its vertices' boundary loop the way
/// the hole runs. Every vertex must be on a boundary or isolated; refuses an edge of the new face that
/// is an interior edge, and a result that is not manifold. Selection: the face's vertices.
Modelled fill(const CovarianceMesh& mesh, const std::vector<int>& vertices);

/// The editor's fill: vertices that make up one whole boundary loop fill it with one face in loop
/// order; exactly 3 or 4 boundary (or isolated) vertices that are not a whole loop get a face ordered
/// along their boundary loop (or, on different loops, by angle around their centroid); anything else
/// is refused with the reason.
Modelled fill_selected(const CovarianceMesh& mesh, const std::vector<int>& vertices);

}  // namespace gps
