#include "core/fitting/limit_weights.h"

#include <algorithm>
#include <numeric>

#include "core/patches/patch_basis.h"
#include "core/plans/plan_descent.h"

namespace gps {

namespace {

// Weights over plan points, gathered before the stencils compose them.
struct PointWeights {
  std::vector<int> point;
  std::vector<double> value, du, dv;
  void add(int p, double w, double wu, double wv) {
    point.push_back(p);
    value.push_back(w);
    du.push_back(wu);
    dv.push_back(wv);
  }
};

// An extraordinary node, as evaluate_extraordinary in patch_eval.cpp: the table rows' weights over its K
// points, carried back through `steps` steps of the table's matrix A (a point after the steps is a row
// of Aˢ, so its weight spreads over the K points by (Aᵀ)ˢ).
void extraordinary_weights(const PatchPlans& plans, int node, double u, double v, double scale_down,
                           PointWeights& out) {
  const int32_t* nodes = plans.nodes.data();
  const int k = nodes[node + 3], net = plans.shape == PatchShape::quad ? 16 : 12;
  double w[16], ws[16], wt[16], d[4], scale;
  int first_row, steps;
  const int n_rows = extraordinary_rows(plans.shape == PatchShape::quad, nodes[node + 1], u, v, true, first_row, steps,
                                        w, ws, wt, d, scale);
  const double* table = plans.extraordinary_tables.data() + nodes[node + 2];
  const double* rows = table + size_t(first_row) * size_t(k);
  Eigen::MatrixX3d a(k, 3);  // per point: weight of q, of q_s, of q_t
  for (int i = 0; i < k; ++i) {
    double x = 0, x_s = 0, x_t = 0;
    for (int j = 0; j < n_rows; ++j) {
      const double r = rows[size_t(j * k + i)];
      x += w[j] * r;
      x_s += ws[j] * r;
      x_t += wt[j] * r;
    }
    a.row(i) << x, x_s, x_t;
  }
  if (steps > 0) {
    const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> step(
        table + size_t(3 * net * kExtraordinaryLevels + 3) * size_t(k), k, k);
    for (int n = 0; n < steps; ++n) a = step.transpose() * a;
  }
  for (int i = 0; i < k; ++i) {
    const double s = scale * scale_down;
    out.add(nodes[node + 4 + i], a(i, 0), s * (d[0] * a(i, 1) + d[1] * a(i, 2)), s * (d[2] * a(i, 1) + d[3] * a(i, 2)));
  }
}

}  // namespace

// Mirrors evaluate_dual in core/evaluation/patch_eval.cpp.
LimitWeights limit_weights(const PatchPlans& plans, const StencilTable& stencils, int patch, double u, double v) {
  const int32_t* nodes = plans.nodes.data();
  double scale;
  int kind, depth;
  const int node = descend_plan(nodes, plans.patch_roots[size_t(patch)], plans.shape == PatchShape::triangle, u, v,
                                scale, kind, depth);
  PointWeights points;
  if (kind == kNodeExtraordinary) {
    extraordinary_weights(plans, node, u, v, scale, points);
  } else {
    double w[16], wu[16], wv[16];
    int n = 12;
    if (plans.shape == PatchShape::triangle) {
      loop_box_spline_basis(u, v, w, wu, wv);
    } else {
      quad_leaf_basis(kind, node_boundary(nodes[node]), u, v, w, wu, wv);
      n = 16;
    }
    for (int j = 0; j < n; ++j) points.add(nodes[node + 1 + j], w[j], scale * wu[j], scale * wv[j]);
  }
  // The plan points as base vertices: a stencil row spreads its weight over the vertices it reads.
  PointWeights vertices;
  for (size_t j = 0; j < points.point.size(); ++j) {
    const int p = points.point[j];
    if (p < stencils.n_base) {
      vertices.add(p, points.value[j], points.du[j], points.dv[j]);
      continue;
    }
    const size_t row = size_t(p - stencils.first_row());
    for (int k = stencils.offsets[row]; k < stencils.offsets[row + 1]; ++k) {
      const double s = stencils.weights[size_t(k)];
      vertices.add(stencils.indices[size_t(k)], s * points.value[j], s * points.du[j], s * points.dv[j]);
    }
  }
  std::vector<int> order(vertices.point.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return vertices.point[size_t(a)] < vertices.point[size_t(b)]; });
  LimitWeights out;
  for (const int j : order) {
    const size_t i = size_t(j);
    if (out.vertex.empty() || out.vertex.back() != vertices.point[i]) {
      out.vertex.push_back(vertices.point[i]);
      out.value.push_back(0);
      out.du.push_back(0);
      out.dv.push_back(0);
    }
    out.value.back() += vertices.value[i];
    out.du.back() += vertices.du[i];
    out.dv.back() += vertices.dv[i];
  }
  return out;
}

void apply_limit_weights(const LimitWeights& weights, const std::vector<Dual>& points, Dual& q, Dual& q_u, Dual& q_v) {
  q.setZero();
  q_u.setZero();
  q_v.setZero();
  for (size_t k = 0; k < weights.size(); ++k) {
    const Dual& p = points[size_t(weights.vertex[k])];
    q += weights.value[k] * p;
    q_u += weights.du[k] * p;
    q_v += weights.dv[k] * p;
  }
}

}  // namespace gps
