#pragma once
// Sliding vertices along the mesh's edges without changing its topology: Blender's edge slide (G G
// on edges) and vertex slide (G G on a vertex). They follow core/modelling/mesh_arrays.h's contract:
// the input is never changed, a refusal throws gps::Error naming the element, every vertex and face
// keeps its index.
//
// A vertex slid a fraction t of the way along its edge to a neighbour u gets the Gaussian
// blend_gaussians((1 − t) q_v + t q_u): the 9D point a linear scheme puts at parameter t of that
// edge, so that sliding commutes with loop_cut and split_edge (a vertex they make at t, slid, is
// the vertex they would have made at the new parameter) and t = 1 lands on u's Gaussian. The mean
// therefore follows the edge's 9D path, which is the straight edge when both covariances are equal.
// At t = 0 and t = 1 the vertex takes its own or u's Gaussian as it is (the blend's end points,
// without rounding).
#include <array>
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "core/modelling/mesh_arrays.h"

namespace gps {

/// Edge slide: the selected edges make loops or chains (no vertex on more than two of them); each
/// vertex on them slides along the edge that leaves the selection on one side, in the faces beside
/// its selected edges. `factor` in [−1, 1] picks the side and the fraction: > 0 toward the faces
/// that hold the first listed edge of each loop or chain as given (a → b: the face on its left, seen
/// from outside), < 0 toward the others; ±1 lands on the neighbouring vertices. With `even` every
/// vertex of a loop or chain moves the same distance (|factor| times the shortest of their slide
/// edges), so the loop keeps its shape; otherwise each moves |factor| of its own edge. Selection:
/// the selected edges' vertices. Refuses an edge not in the mesh, a vertex on more than two selected
/// edges, |factor| > 1, and a vertex with no edge, or two different edges, leaving the selection on
/// the chosen side (the boundary, or a vertex of valence other than 4 between quads there).
Modelled edge_slide(const CovarianceMesh& mesh, const std::vector<std::array<int, 2>>& edges, double factor,
                    bool even = false);

/// Vertex slide: `vertex` moves the fraction `factor` in [0, 1] along its edge to `toward`.
/// Selection: the vertex. Refuses {vertex, toward} not an edge and a factor outside [0, 1].
Modelled vertex_slide(const CovarianceMesh& mesh, int vertex, int toward, double factor);

}  // namespace gps
