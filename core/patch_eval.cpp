#include "core/patch_eval.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include "core/patch_basis.h"

namespace gps {

void evaluate_dual(const PlanTable& plans, const std::vector<Dual>& points, int patch, double u, double v, Dual& q,
                   Dual& q_u, Dual& q_v, int* depth_out, NodeKind* kind_out) {
  int node = plans.patch_roots[size_t(patch)];
  double scale = 1.0;  // d(node parameter)/d(patch parameter)
  int depth = 0;
  while (NodeKind(plans.nodes[size_t(node)]) == NodeKind::internal) {
    const int ubit = u >= 0.5 ? 1 : 0, vbit = v >= 0.5 ? 1 : 0;
    u = 2.0 * u - ubit;
    v = 2.0 * v - vbit;
    scale *= 2.0;
    ++depth;
    node = plans.nodes[size_t(node + 1 + ubit + 2 * vbit)];
  }
  const NodeKind kind = NodeKind(plans.nodes[size_t(node)]);
  double wu[4], dwu[4], wv[4], dwv[4];
  if (kind == NodeKind::regular) {
    bspline_basis(u, wu, dwu);
    bspline_basis(v, wv, dwv);
  } else {
    bezier_basis(u, wu, dwu);
    bezier_basis(v, wv, dwv);
  }
  q.setZero();
  q_u.setZero();
  q_v.setZero();
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const Dual& p = points[size_t(plans.nodes[size_t(node + 1 + i + 4 * j)])];
      q += (wu[i] * wv[j]) * p;
      q_u += (dwu[i] * wv[j]) * p;
      q_v += (wu[i] * dwv[j]) * p;
    }
  q_u *= scale;
  q_v *= scale;
  if (depth_out) *depth_out = depth;
  if (kind_out) *kind_out = kind;
}

std::optional<PatchSample> evaluate_patch(const PlanTable& plans, const std::vector<Dual>& points, int patch, double u,
                                          double v) {
  PatchSample s;
  evaluate_dual(plans, points, patch, u, v, s.q, s.q_u, s.q_v, &s.depth, &s.kind);
  const Eigen::LLT<Mat3> llt(unvech(s.q));
  if (llt.info() != Eigen::Success) return std::nullopt;
  s.position = llt.solve(Vec3(s.q.tail<3>()));
  s.covariance = llt.solve(Mat3::Identity());
  // Eq. 3.12: μ_u = [q̂]⁻¹ (q̄_u − [q̂_u] μ).
  s.du = llt.solve(Vec3(s.q_u.tail<3>()) - unvech(s.q_u) * s.position);
  s.dv = llt.solve(Vec3(s.q_v.tail<3>()) - unvech(s.q_v) * s.position);
  s.normal = s.du.cross(s.dv).normalized();
  return s;
}

}  // namespace gps
