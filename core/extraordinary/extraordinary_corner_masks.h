#pragma once
// The limit position and tangent masks at an extraordinary vertex, from the subdivision step of
// its neighbourhood (core/extraordinary/loop_extraordinary_tables.h, core/extraordinary/quad_extraordinary_tables.h):
// generic for interior and boundary vertices of either scheme, exact also where the step matrix is not diagonalisable.
#include <Eigen/Core>

namespace gps {

struct CornerMasks {
  Eigen::RowVectorXd position;  // weights of the K points: the limit position
  Eigen::RowVectorXd d_s, d_t;  // two tangents, in the orientation of the node's (s, t)
};

/// `step` (K×K) maps the K points around the vertex to those one subdivision level finer; `d_s`,
/// `d_t` are the s and t derivative masks of a regular child's patch next to the vertex. The
/// position is a row of stepⁿ as n → ∞ (power iteration of one row, repeated squaring where that is
/// slow). The tangents are the dominant
/// invariant subspace of the rows d·stepⁿ with the position's part taken out (subspace iteration,
/// Gram–Schmidt kept orientation-preserving), so d_s × d_t points the way the patch's normal does;
/// their lengths are not derivatives (the vertex's own scale is λⁿ, not 2ⁿ), only their directions are.
CornerMasks extraordinary_corner_masks(const Eigen::MatrixXd& step, const Eigen::RowVectorXd& d_s,
                                       const Eigen::RowVectorXd& d_t);

}  // namespace gps
