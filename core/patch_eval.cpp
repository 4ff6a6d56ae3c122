#include "core/patch_eval.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include "core/patch_basis.h"

namespace gps {

namespace {

// An extraordinary node (core/loop_ev_tables.h, core/quad_ev_tables.h) at (u, v) of its own
// domain: turned so that its extraordinary corner is at (0, 0), located in a regular child n
// levels down, whose net is a block of the node's table times its K points; at the corner the
// limit masks. Mirrors evaluate_extraordinary_node in shaders/plan_eval.glsl.
void evaluate_extraordinary(const PlanTable& plans, const std::vector<Dual>& points, int node, double u, double v, Dual& q,
                            Dual& q_u, Dual& q_v) {
  const int32_t* nodes = plans.nodes.data();
  const bool quad = plans.shape == PatchShape::quad;
  const int r = nodes[node + 1], k = nodes[node + 3], net = quad ? 16 : 12;
  const double* table = plans.ev_tables.data() + nodes[node + 2];
  double s, t, scale, d[4];
  int block;
  if (quad) {
    quad_turn_to_corner(r, u, v, s, t);
    quad_turned_derivative_coefficients(r, d);
    block = quad_ev_locate(s, t, scale);
  } else {
    triangle_turn_to_corner(r, u, v, s, t);
    triangle_turned_derivative_coefficients(r, d);
    block = loop_ev_locate(s, t, scale);
  }
  double w[16], ws[16], wt[16];
  const double* rows;
  int n_rows;
  if (block >= 0) {
    if (quad) bspline_patch_basis(s, t, w, ws, wt);
    else loop_box_spline_basis(s, t, w, ws, wt);
    rows = table + size_t(net * block) * size_t(k);
    n_rows = net;
  } else {  // the limit masks: rows 0, 1, 2 are position, d/ds, d/dt
    w[0] = 1.0, ws[0] = 0.0, wt[0] = 0.0, w[1] = 0.0, ws[1] = 1.0, wt[1] = 0.0, w[2] = 0.0, ws[2] = 0.0, wt[2] = 1.0;
    rows = table + size_t(3 * net * kEvLevels) * size_t(k);
    n_rows = 3;
    scale = 1.0;
  }
  q.setZero();
  Dual q_s = Dual::Zero(), q_t = Dual::Zero();
  for (int i = 0; i < k; ++i) {
    double a = 0.0, a_s = 0.0, a_t = 0.0;
    for (int j = 0; j < n_rows; ++j) {
      const double x = rows[size_t(j * k + i)];
      a += w[j] * x;
      a_s += ws[j] * x;
      a_t += wt[j] * x;
    }
    const Dual& p = points[size_t(nodes[node + 4 + i])];
    q += a * p;
    q_s += a_s * p;
    q_t += a_t * p;
  }
  q_u = scale * (d[0] * q_s + d[1] * q_t);
  q_v = scale * (d[2] * q_s + d[3] * q_t);
}

// A triangle plan (core/plan_table.h, Loop): descend with triangle_child(), then a box-spline
// node or an extraordinary node; mirrors shaders/loop_eval.glsl.
void evaluate_triangle_dual(const PlanTable& plans, const std::vector<Dual>& points, int patch, double u, double v,
                            Dual& q, Dual& q_u, Dual& q_v, int* depth_out, NodeKind* kind_out) {
  const int32_t* nodes = plans.nodes.data();
  int node = plans.patch_roots[size_t(patch)];
  double scale = 1.0;  // d(node parameter)/d(patch parameter), with the half turns of middle children
  int depth = 0;
  while (nodes[node] == kNodeInternal) {
    double sign = 1.0;
    const int child = triangle_child(u, v, sign);
    scale *= 2.0 * sign;
    ++depth;
    node = nodes[node + 1 + child];
  }
  const int kind = nodes[node];
  if (kind == kNodeRegular) {
    q.setZero();
    q_u.setZero();
    q_v.setZero();
    double w[12], wu[12], wv[12];
    loop_box_spline_basis(u, v, w, wu, wv);
    for (int j = 0; j < 12; ++j) {
      const Dual& p = points[size_t(nodes[node + 1 + j])];
      q += w[j] * p;
      q_u += wu[j] * p;
      q_v += wv[j] * p;
    }
  } else {
    evaluate_extraordinary(plans, points, node, u, v, q, q_u, q_v);
  }
  q_u *= scale;
  q_v *= scale;
  if (depth_out) *depth_out = depth;
  if (kind_out) *kind_out = NodeKind(kind);
}

}  // namespace

void evaluate_dual(const PlanTable& plans, const std::vector<Dual>& points, int patch, double u, double v, Dual& q,
                   Dual& q_u, Dual& q_v, int* depth_out, NodeKind* kind_out) {
  if (plans.shape == PatchShape::triangle) return evaluate_triangle_dual(plans, points, patch, u, v, q, q_u, q_v, depth_out, kind_out);
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
  if (kind == NodeKind::extraordinary) {
    evaluate_extraordinary(plans, points, node, u, v, q, q_u, q_v);
    q_u *= scale;
    q_v *= scale;
    if (depth_out) *depth_out = depth;
    if (kind_out) *kind_out = kind;
    return;
  }
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
