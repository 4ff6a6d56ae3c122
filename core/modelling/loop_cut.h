#pragma once
// Loop cuts: new edge loops across a ring of quads (the edges a cut through one edge crosses), the
// new vertices on the ring's edges with the 9D blends of the edges' ends. Operations follow
// core/modelling/mesh_arrays.h's contract: the input is never changed, a refusal throws gps::Error,
// kept vertices and faces keep their indices, new ones are appended.
#include <array>
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "core/modelling/mesh_arrays.h"

namespace gps {

/// The edges a loop cut through edge {a, b} crosses, in order along the ring, each directed with its
/// first end on a's side of the cut (the start edge as a → b). From {a, b} the ring goes across each
/// quad to its opposite edge, both ways, until a face that is not a quad, the boundary, or the start
/// again (closed: then it begins at a → b; open: it runs from one end to the other).
struct EdgeRing {
  std::vector<std::array<int, 2>> edges;
  bool closed = false;
};
/// Throws gps::Error naming the edge when {a, b} is not an edge of the mesh.
EdgeRing edge_ring(const CovarianceMesh& mesh, int a, int b);

/// `cuts` (1..64) new edge loops across the ring through {a, b}: on each ring edge x → y, new
/// vertices at fractions t_k = s_k (1 + slide) for slide ≤ 0 and s_k + slide (1 − s_k) for slide > 0,
/// s_k = k / (cuts + 1), each with the Gaussian blend_gaussians((1 − t_k) q_x + t_k q_y). Every quad of
/// the ring splits into cuts + 1 quads (the piece on a's side keeps the face's index), a face at an
/// open ring's end that is not a quad takes the new vertices on its edge as extra corners. New
/// vertices: ring edge by ring edge, each from its first end. Selection: the new vertices. Refuses
/// {a, b} not an edge or without a quad beside it, cuts out of range, |slide| ≥ 1, and a ring that
/// crosses itself.
Modelled loop_cut(const CovarianceMesh& mesh, int a, int b, int cuts = 1, double slide = 0.0);

}  // namespace gps
