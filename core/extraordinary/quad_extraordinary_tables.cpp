#include "core/extraordinary/quad_extraordinary_tables.h"

#include <Eigen/SparseCore>
#include <algorithm>
#include <stdexcept>

#include "core/extraordinary/extraordinary_corner_masks.h"
#include "core/extraordinary/neighbourhood_signature.h"
#include "core/patches/quad_nets.h"

namespace gps {

std::optional<NeighbourhoodSignature> quad_extraordinary_neighbourhood(const LocalMesh& m,
                                                                      const std::array<int, 4>& c) {
  return neighbourhood_signature(m, {c[0], c[1], c[2], c[3]});
}

namespace {

std::shared_ptr<const std::vector<double>> compute_table(const std::vector<int>& signature) {
  const LocalMesh coarse = neighbourhood_mesh(signature, 4);
  const LocalMesh fine = refine_local_mesh(coarse);
  const int k = coarse.topology().n_vertices, ne = coarse.connectivity().n_edges();
  const auto edge_point = [&](int a, int b) { return k + coarse.find_edge(a, b); };
  const int face_point = k + ne + 0, e01 = edge_point(0, 1), e12 = edge_point(1, 2), e23 = edge_point(2, 3),
            e30 = edge_point(3, 0);
  // A: the corner child (0', e01, f, e30) must have the same neighbourhood, one level down.
  const auto child = quad_extraordinary_neighbourhood(fine, {0, e01, face_point, e30});
  if (!child || child->signature != signature) return nullptr;
  std::vector<LocalCombination> step_rows;
  for (const int p : child->points) step_rows.push_back({{p, 1.0}});
  const Eigen::MatrixXd step = rows_over_neighbourhood(fine, step_rows, k);
  // Ā_c: the nets of children 1..3 (quadrants s ≥ ½ > t, both ≥ ½, t ≥ ½ > s), each from its (0, 0).
  const std::array<int, 4> children[3] = {
      {e01, 1, e12, face_point}, {face_point, e12, 2, e23}, {e30, face_point, e23, 3}};
  Eigen::MatrixXd nets[3];
  for (int c = 0; c < 3; ++c) {
    const int face = fine.find_face({children[c][0], children[c][1], children[c][2], children[c][3]});
    for (const int v : children[c])
      if (!regular_corner(fine, v, face)) return nullptr;
    std::array<LocalCombination, 16> net;
    bspline_net(fine, face, children[c], net);
    nets[c] = rows_over_neighbourhood(fine, {net.begin(), net.end()}, k);
  }
  auto table = std::make_shared<std::vector<double>>(quad_extraordinary_table_size(k), 0.0);
  Eigen::MatrixXd power = Eigen::MatrixXd::Identity(k, k);
  const Eigen::SparseMatrix<double> sparse_step = step.sparseView();  // a rule reads a few points
  for (int level = 0; level < kExtraordinaryLevels; ++level) {
    for (int c = 0; c < 3; ++c) {
      const Eigen::MatrixXd block = nets[c] * power;
      for (int j = 0; j < 16; ++j)
        for (int i = 0; i < k; ++i) (*table)[size_t((3 * level + c) * 16 + j) * size_t(k) + size_t(i)] = block(j, i);
    }
    power = sparse_step * power;
  }
  // Tangents start from child 1's patch at its corner (½, 0), next to the vertex.
  double w[4], dw[4];
  bspline_basis(0.0, w, dw);
  Eigen::RowVectorXd d_s = Eigen::RowVectorXd::Zero(k), d_t = Eigen::RowVectorXd::Zero(k);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      d_s += dw[i] * w[j] * nets[0].row(i + 4 * j);
      d_t += w[i] * dw[j] * nets[0].row(i + 4 * j);
    }
  const CornerMasks masks = extraordinary_corner_masks(step, d_s, d_t);
  double* rows = table->data() + size_t(48 * kExtraordinaryLevels) * size_t(k);
  for (int i = 0; i < k; ++i) {
    rows[i] = masks.position(i);
    rows[k + i] = masks.d_s(i);
    rows[2 * k + i] = masks.d_t(i);
  }
  for (int r = 0; r < k; ++r)
    for (int i = 0; i < k; ++i) rows[size_t(3 + r) * size_t(k) + size_t(i)] = step(r, i);
  return table;
}

}  // namespace

std::shared_ptr<const std::vector<double>> QuadExtraordinaryTableCache::table(const std::vector<int>& signature) {
  {
    const std::lock_guard lock(mutex_);
    if (const auto it = tables_.find(signature); it != tables_.end()) return it->second;
  }
  auto computed = compute_table(signature);  // outside the lock: threads meeting other signatures go on
  const std::lock_guard lock(mutex_);
  return tables_.try_emplace(signature, std::move(computed)).first->second;
}

}  // namespace gps
