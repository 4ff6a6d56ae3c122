#pragma once
// A vertex's ring in order and one subdivision step of it as a matrix, for the masks that are left
// eigenvectors of that step (core/reference/limit_tangents.h, core/reference/dart_masks.h).
#include <Eigen/Core>

#include <vector>

#include "core/mesh/mesh_connectivity.h"
#include "core/reference/loop.h"

namespace gps {

/// The ring of v in counter-clockwise order (faces oriented counter-clockwise): edge neighbours
/// e_0 … e_m and, for quads, the corner f_i across face i (between e_i and e_{i+1}). For an interior
/// vertex m = n − 1 (e_0 is not repeated); on a boundary e_0 and e_m are the boundary neighbours.
struct OrderedRing {
  std::vector<int> edges, diagonals;
  bool boundary = false;
};

/// v's ring when every face around v has `face_size` corners (4: quads, 3: triangles) and they form
/// one fan; false otherwise.
bool ordered_ring(const PolygonTopology& t, const MeshConnectivity& c, int v, int face_size, OrderedRing& ring);

/// The matrix of one step of our own rules (catmull_clark_values, loop_values with `kind`) on a fan
/// of k faces around a vertex: rows and columns (v, e_0 … e_m, f_0 … f_{k−1}) for quads,
/// (v, e_0 … e_m) for triangles, numbered as OrderedRing (m = k on a boundary, k − 1 inside); each
/// row the refined point's weights on the coarse ones. With `sharp_edge` ≥ 0 the edge (v, e_sharp_edge)
/// is infinitely sharp.
Eigen::MatrixXd ring_step_matrix(int k, bool quads, bool boundary, LoopBeta kind, int sharp_edge = -1);

/// The left eigenvectors of `step` for its subdominant eigenvalues (second and third in magnitude),
/// which applied to a ring at any level give its limit tangents. Signed so that on the ring laid flat
/// (`flat`: a row (x, y) per point, the faces counter-clockwise) the first turns counter-clockwise into
/// the second: first × second is then the normal on the side the faces' corners turn to. Empty where
/// the largest eigenvalue is not 1, those three are not real, the third is not above all the others
/// or the pair spans no plane: then the ring has no tangent plane of two modes to take.
std::vector<Eigen::VectorXd> tangent_eigenvectors(const Eigen::MatrixXd& step, const Eigen::MatrixXd& flat);

}  // namespace gps
