#include "core/extraordinary/extraordinary_corner_masks.h"

#include <Eigen/SparseCore>
#include <algorithm>
#include <stdexcept>

namespace gps {

namespace {

// The limit position mask by repeated squaring of the whole step: stepⁿ for n = 2^20 at most (every row
// converges to the limit mask: eigenvalue 1, all others smaller in size); the rows are kept affine
// (summing to 1), so rounding cannot grow eigenvalue 1. K³ a squaring: the fallback of the power
// iteration below, for steps whose next eigenvalue is close to 1.
Eigen::RowVectorXd position_by_squaring(const Eigen::MatrixXd& step) {
  Eigen::MatrixXd power = step;
  for (int i = 0; i < 20; ++i) {
    Eigen::MatrixXd next = power * power;
    for (Eigen::Index r = 0; r < next.rows(); ++r) next.row(r) /= next.row(r).sum();
    const double change = (next - power).cwiseAbs().maxCoeff();
    power = next;
    if (change < 1e-16) break;
  }
  const Eigen::RowVectorXd position = power.row(0);
  if ((power.rowwise() - position).cwiseAbs().maxCoeff() > 1e-12)
    throw std::logic_error("extraordinary corner: the subdivision step does not converge to one limit point");
  return position;
}

}  // namespace

CornerMasks extraordinary_corner_masks(const Eigen::MatrixXd& step, const Eigen::RowVectorXd& d_s,
                                       const Eigen::RowVectorXd& d_t) {
  CornerMasks masks;
  // A step reads a few points per row (a subdivision rule), so its products are sparse ones: at a
  // vertex of valence n a row vector costs O(n), not O(n²).
  const Eigen::SparseMatrix<double> sparse = step.sparseView();
  // The position: a row of stepⁿ as n → ∞, by the power iteration of one row kept affine; it converges
  // as the next eigenvalue's size to the n. Where that is slow, by squaring.
  Eigen::RowVectorXd position = step.row(0);
  bool converged = false;
  for (int i = 0; i < 2000 && !converged; ++i) {
    Eigen::RowVectorXd next = position * sparse;
    next /= next.sum();
    converged = (next - position).cwiseAbs().maxCoeff() < 1e-16;
    position = next;
  }
  masks.position = converged ? position : position_by_squaring(step);
  // Subspace iteration on {d_s, d_t}; the limit's own part (weights summing to 1) is removed each
  // step. It converges as (|λ₄| / |λ₃|)ⁿ: at high valences the next eigenvalue is close (0.95 of the
  // subdominant one at Catmull-Clark valence 16, 0.997 at 64), so it runs until the masks stop
  // changing (by 1e-14; rounding alone moves them by ~1e-16), not a fixed count, four subdivision
  // steps at a time (the tangent pair keeps all but about one digit of its weaker direction between
  // two orthogonalisations). The pair is the rows of one 2×K matrix, stepped together.
  Eigen::Matrix<double, 2, Eigen::Dynamic> pair(2, step.cols()), stepped(2, step.cols()), last(2, step.cols());
  pair.row(0) = d_s;
  pair.row(1) = d_t;
  for (int i = 0; i < 12500; ++i) {
    last = pair;
    for (int k = 0; k < 4; ++k) {
      stepped.noalias() = pair * sparse;
      pair.swap(stepped);
    }
    for (int r = 0; r < 2; ++r) pair.row(r) -= pair.row(r).sum() * masks.position;
    pair.row(0) /= pair.row(0).norm();
    pair.row(1) -= pair.row(1).dot(pair.row(0)) * pair.row(0);
    pair.row(1) /= pair.row(1).norm();
    if (i >= 50 && (pair - last).cwiseAbs().maxCoeff() < 1e-14) break;
  }
  masks.d_s = pair.row(0);
  masks.d_t = pair.row(1);
  return masks;
}

}  // namespace gps
