#include "core/extraordinary/extraordinary_corner_masks.h"

#include <algorithm>
#include <stdexcept>

namespace gps {

CornerMasks extraordinary_corner_masks(const Eigen::MatrixXd& step, Eigen::RowVectorXd d_s, Eigen::RowVectorXd d_t) {
  CornerMasks masks;
  // stepⁿ for n = 2^20 at most (every row converges to the limit mask: eigenvalue 1, all others
  // smaller in size); the rows are kept affine (summing to 1), so rounding cannot grow eigenvalue 1.
  Eigen::MatrixXd power = step;
  for (int i = 0; i < 20; ++i) {
    Eigen::MatrixXd next = power * power;
    for (Eigen::Index r = 0; r < next.rows(); ++r) next.row(r) /= next.row(r).sum();
    const double change = (next - power).cwiseAbs().maxCoeff();
    power = next;
    if (change < 1e-16) break;
  }
  masks.position = power.row(0);
  if ((power.rowwise() - masks.position).cwiseAbs().maxCoeff() > 1e-12)
    throw std::logic_error("extraordinary corner: the subdivision step does not converge to one limit point");
  // Subspace iteration on {d_s, d_t}; the limit's own part (weights summing to 1) is removed each
  // step. It converges as (|λ₄| / |λ₃|)ⁿ: at high valences the next eigenvalue is close (0.95 of the
  // subdominant one at Catmull-Clark valence 16, 0.997 at 64), so it runs until the masks stop
  // changing (by 1e-14; rounding alone moves them by ~1e-16), not a fixed count, four subdivision
  // steps at a time (step⁴: a quarter of the matrix-vector products; the tangent pair keeps all but
  // about one digit of its weaker direction between two orthogonalisations).
  const Eigen::MatrixXd step2 = step * step;
  const Eigen::MatrixXd step4 = step2 * step2;
  const auto without_position = [&](Eigen::RowVectorXd r) { return Eigen::RowVectorXd(r - r.sum() * masks.position); };
  for (int i = 0; i < 12500; ++i) {
    const Eigen::RowVectorXd last_s = d_s, last_t = d_t;
    d_s = without_position(d_s * step4);
    d_t = without_position(d_t * step4);
    const double length = d_s.norm();
    d_s /= length;
    d_t -= d_t.dot(d_s) * d_s;
    d_t /= d_t.norm();
    if (i >= 50 && std::max((d_s - last_s).cwiseAbs().maxCoeff(), (d_t - last_t).cwiseAbs().maxCoeff()) < 1e-14) break;
  }
  masks.d_s = d_s;
  masks.d_t = d_t;
  return masks;
}

}  // namespace gps
