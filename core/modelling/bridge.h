#pragma once
// Bridging: joining two boundary loops (or two open boundary chains) of equal length with a band of quads.
//
// Like every modelling operation (core/modelling/mesh_arrays.h) these take a mesh and return a new
// one with a selection and a one-line summary, never changing their input; on refusal they throw
// gps::Error with a one-line reason and nothing is changed. The quads are appended; no vertex is
// added or moved.
#include <vector>

#include "core/modelling/mesh_arrays.h"

namespace gps {

/// Joins two boundary loops, each given as its vertices in any rotation and either direction and
/// forming a whole boundary loop, or two open boundary chains (consecutive vertices joined by
/// boundary edges) of the same length, with a band of quads. Vertex i of the first is paired with the
/// second's vertices in the direction that keeps the orientation consistent (the two run opposite
/// ways along their faces' edges); for loops, the start is the one that minimises the summed squared
/// distances of paired vertices. Refuses loops of different lengths, vertices not on a boundary,
/// vertices in both, a loop with a chain, and a result that is not manifold. Selection: both loops' vertices.
Modelled bridge(const CovarianceMesh& mesh, const std::vector<int>& loop_a, const std::vector<int>& loop_b);

/// The editor's bridge: the selected vertices, split by the boundary edges between them into exactly
/// two boundary loops (or two chains), bridged as above.
Modelled bridge_selected(const CovarianceMesh& mesh, const std::vector<int>& vertices);

}  // namespace gps
