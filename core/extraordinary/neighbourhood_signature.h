#pragma once
// The neighbourhood of a node at its one irregular corner, as the exact extraordinary tables of both
// schemes know it (core/extraordinary/quad_extraordinary_tables.h, loop_crease_tables.h): the faces at
// the node's corners in a canonical walk, with the infinitely sharp edges and vertices among them.
// A table depends on nothing else, so nodes with equal signatures share one.
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/patches/local_mesh.h"
#include "core/patches/quad_nets.h"

namespace gps {

struct NeighbourhoodSignature {
  std::vector<int> points;     // vertices of the LocalMesh, in canonical order; the node's corners first
  std::vector<int> signature;  // per face in walk order: its size, then its vertices' canonical numbers;
                               // then the sharp edges and vertices (neighbourhood_mesh reads them back)
};

/// The neighbourhood of the face with corners `corners` (in its face order, corners[0] the irregular
/// one): the faces at the corners, walked breadth first across their edges from the node's face.
/// Empty where the walk does not reach them all, or where an edge or vertex among them is semi-sharp
/// (its sharpness decays, so the neighbourhood is not self-similar).
std::optional<NeighbourhoodSignature> neighbourhood_signature(const LocalMesh& m, const std::vector<int>& corners);

/// The neighbourhood of a signature as a LocalMesh of its own, with its sharp edges and vertices:
/// point i is the unit vector e_i, the first `n_corners` points complete.
LocalMesh neighbourhood_mesh(const std::vector<int>& signature, int n_corners);

/// Rows of combinations of `fine`'s points as a matrix over the K points of the coarse neighbourhood.
Eigen::MatrixXd rows_over_neighbourhood(const LocalMesh& fine, const std::vector<LocalCombination>& rows, int k);

}  // namespace gps
