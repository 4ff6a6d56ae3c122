#pragma once
// Operations on one edge: splitting it at a 9D blend of its ends, and flipping the diagonal between
// two triangles. They follow core/modelling/mesh_arrays.h's contract: the input is never changed, a
// refusal throws gps::Error naming the edge, kept vertices and faces keep their indices, new ones are
// appended.
#include "core/mesh/covariance_mesh.h"
#include "core/modelling/mesh_arrays.h"

namespace gps {

/// A new vertex on edge {a, b} at fraction t in (0, 1) from a, with the Gaussian
/// blend_gaussians((1 − t) q_a + t q_b). Each triangle beside the edge splits in two through it and
/// the opposite corner (the piece at a keeps the face's index), any other face beside it takes it as
/// an extra corner. Selection: the new vertex. Refuses {a, b} not an edge and t outside (0, 1).
Modelled split_edge(const CovarianceMesh& mesh, int a, int b, double t = 0.5);

/// The vertex split_edge puts on edge {a, b} at fraction t from a, added to `arrays` for operations
/// that cut edges (bisect, knife): the Gaussian blend_gaussians((1 − t) q_a + t q_b), the edge's
/// crease on both halves; the faces are left to the caller. Returns its index.
int add_edge_vertex(MeshArrays& arrays, int a, int b, double t);

/// The edge {a, b} shared by two triangles replaced by the other diagonal of the quad they make
/// (each triangle keeps its index). Selection: the new edge's two vertices. Refuses a boundary edge,
/// a neighbour that is not a triangle, and a flip that would duplicate an existing edge.
Modelled flip_edge(const CovarianceMesh& mesh, int a, int b);

}  // namespace gps
