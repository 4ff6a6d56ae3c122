#include "core/evaluation/patch_eval.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include "core/patches/patch_basis.h"
#include "core/plans/plan_descent.h"

namespace gps {

namespace {

// An extraordinary node at (u, v) of its own domain: the rows of extraordinary_rows()
// (core/plans/plan_descent.h) of its table times its K points, stepped by the table's A past its levels.
void evaluate_extraordinary(const PatchPlans& plans, const std::vector<Dual>& points, int node, double u, double v,
                            Dual& q, Dual& q_u, Dual& q_v) {
  const int32_t* nodes = plans.nodes.data();
  const int k = nodes[node + 3], net = plans.shape == PatchShape::quad ? 16 : 12;
  double w[16], ws[16], wt[16], d[4], scale;
  int first_row, steps;
  const int n_rows = extraordinary_rows(plans.shape == PatchShape::quad, nodes[node + 1], u, v, true, first_row, steps,
                                        w, ws, wt, d, scale);
  const double* table = plans.extraordinary_tables.data() + nodes[node + 2];
  const double* rows = table + size_t(first_row) * size_t(k);
  std::vector<Dual> stepped;  // the K points after `steps` steps of A, where there are any
  if (steps > 0) {
    const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> step(
        table + size_t(3 * net * kExtraordinaryLevels + 3) * size_t(k), k, k);
    Eigen::Matrix<double, Eigen::Dynamic, 9> c(k, 9);
    for (int i = 0; i < k; ++i) c.row(i) = points[size_t(nodes[node + 4 + i])].transpose();
    for (int n = 0; n < steps; ++n) c = step * c;
    for (int i = 0; i < k; ++i) stepped.push_back(c.row(i).transpose());
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
    const Dual& p = steps > 0 ? stepped[size_t(i)] : points[size_t(nodes[node + 4 + i])];
    q += a * p;
    q_s += a_s * p;
    q_t += a_t * p;
  }
  q_u = scale * (d[0] * q_s + d[1] * q_t);
  q_v = scale * (d[2] * q_s + d[3] * q_t);
}

// A regular or terminal leaf: its net of `n` points times the basis weights w, wu, wv.
void evaluate_net(const std::vector<Dual>& points, const int32_t* net, int n, const double* w, const double* wu,
                  const double* wv, Dual& q, Dual& q_u, Dual& q_v) {
  q.setZero();
  q_u.setZero();
  q_v.setZero();
  for (int j = 0; j < n; ++j) {
    const Dual& p = points[size_t(net[j])];
    q += w[j] * p;
    q_u += wu[j] * p;
    q_v += wv[j] * p;
  }
}

}  // namespace

// Mirrors evaluate_plan in shaders/plan_eval.glsl and evaluate_triangle_plan in shaders/loop_eval.glsl;
// the descent and the extraordinary rows are one source for both (core/plans/plan_descent.h).
void evaluate_dual(const PatchPlans& plans, const std::vector<Dual>& points, int patch, double u, double v, Dual& q,
                   Dual& q_u, Dual& q_v, int* depth_out, NodeKind* kind_out) {
  const int32_t* nodes = plans.nodes.data();
  double scale;
  int kind, depth;
  const int node = descend_plan(nodes, plans.patch_roots[size_t(patch)], plans.shape == PatchShape::triangle, u, v,
                                scale, kind, depth);
  if (kind == kNodeExtraordinary) {
    evaluate_extraordinary(plans, points, node, u, v, q, q_u, q_v);
  } else if (plans.shape == PatchShape::triangle) {
    double w[12], wu[12], wv[12];
    loop_box_spline_basis(u, v, w, wu, wv);
    evaluate_net(points, nodes + node + 1, 12, w, wu, wv, q, q_u, q_v);
  } else {
    double w[16], wu[16], wv[16];
    quad_leaf_basis(kind, node_boundary(nodes[node]), u, v, w, wu, wv);
    evaluate_net(points, nodes + node + 1, 16, w, wu, wv, q, q_u, q_v);
  }
  q_u *= scale;
  q_v *= scale;
  if (depth_out) *depth_out = depth;
  if (kind_out) *kind_out = NodeKind(kind);
}

namespace {

// The sample at (u, v), its normal that of its tangents as they are.
std::optional<PatchSample> sample_at(const PatchPlans& plans, const std::vector<Dual>& points, int patch, double u,
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

}  // namespace

bool tangents_parallel(const Vec3& du, const Vec3& dv) {
  return !(du.cross(dv).squaredNorm() > kParallelSine * kParallelSine * du.squaredNorm() * dv.squaredNorm());
}

std::optional<PatchSample> evaluate_patch(const PatchPlans& plans, const std::vector<Dual>& points, int patch, double u,
                                          double v) {
  std::optional<PatchSample> s = sample_at(plans, points, patch, u, v);
  if (!s || !tangents_parallel(s->du, s->dv)) return s;
  const double centre = plans.shape == PatchShape::quad ? 0.5 : 1.0 / 3.0;
  const std::optional<PatchSample> beside =
      sample_at(plans, points, patch, u + kFoldStep * (centre - u), v + kFoldStep * (centre - v));
  s->normal = beside && !tangents_parallel(beside->du, beside->dv) ? beside->normal : Vec3::Zero();
  return s;
}

}  // namespace gps
