#include "core/extraordinary/loop_extraordinary_tables.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <stdexcept>

#include "core/extraordinary/extraordinary_corner_masks.h"
#include "core/patches/loop_nets.h"

namespace gps {

namespace {

// Rows of `values` (vectors over the coarse vertices) as a matrix over the coarse points `columns`;
// a weight on any other vertex means the neighbourhood was not complete: a bug, not bad input.
Eigen::MatrixXd restrict_rows(const std::vector<Eigen::VectorXd>& rows, const std::vector<int>& columns) {
  Eigen::MatrixXd m(long(rows.size()), long(columns.size()));
  for (size_t r = 0; r < rows.size(); ++r) {
    Eigen::VectorXd rest = rows[r];
    for (size_t c = 0; c < columns.size(); ++c) {
      m(long(r), long(c)) = rows[r](columns[c]);
      rest(columns[c]) = 0.0;
    }
    if (rest.cwiseAbs().maxCoeff() > 1e-12 || std::abs(m.row(long(r)).sum() - 1.0) > 1e-9)
      throw std::logic_error("Loop extraordinary table: a subdivided point reads outside its neighbourhood");
  }
  return m;
}

}  // namespace

void write_loop_extraordinary_table(const Eigen::MatrixXd (&nets)[3], const Eigen::MatrixXd& step, double* table) {
  const int k = int(step.rows());
  Eigen::MatrixXd power = Eigen::MatrixXd::Identity(k, k);
  const Eigen::SparseMatrix<double> sparse_step = step.sparseView();  // a rule reads a few points
  for (int level = 0; level < kExtraordinaryLevels; ++level) {
    for (int c = 0; c < 3; ++c) {
      const Eigen::MatrixXd block = nets[c] * power;
      for (int j = 0; j < 12; ++j)
        for (int i = 0; i < k; ++i) table[size_t((3 * level + c) * 12 + j) * size_t(k) + size_t(i)] = block(j, i);
    }
    power = sparse_step * power;
  }
  // Limit masks at v (core/extraordinary/extraordinary_corner_masks.h), the tangents from child 1's patch at its
  // corner.
  double w[12], ws[12], wt[12];
  loop_box_spline_basis(0.0, 0.0, w, ws, wt);
  Eigen::RowVectorXd d_s = Eigen::RowVectorXd::Zero(k), d_t = Eigen::RowVectorXd::Zero(k);
  for (int j = 0; j < 12; ++j) {
    d_s += ws[j] * nets[0].row(j);
    d_t += wt[j] * nets[0].row(j);
  }
  const CornerMasks corner = extraordinary_corner_masks(step, d_s, d_t);
  double* masks = table + size_t(36 * kExtraordinaryLevels) * size_t(k);
  for (int i = 0; i < k; ++i) {
    masks[i] = corner.position(i);
    masks[k + i] = corner.d_s(i);
    masks[2 * k + i] = corner.d_t(i);
  }
  for (int r = 0; r < k; ++r)
    for (int i = 0; i < k; ++i) masks[size_t(3 + r) * size_t(k) + size_t(i)] = step(r, i);
}

std::shared_ptr<const std::vector<double>> LoopExtraordinaryTableCache::table(
    const LoopExtraordinaryConfiguration& configuration, const PolygonTopology& mesh,
    const MeshConnectivity& connectivity, int v, int a, int b) {
  {
    const std::lock_guard lock(mutex_);
    if (const auto it = tables_.find(configuration); it != tables_.end()) return it->second;
  }
  auto computed = compute(mesh, connectivity, v, a, b);  // outside the lock: threads meeting others go on
  const std::lock_guard lock(mutex_);
  return tables_.try_emplace(configuration, std::move(computed)).first->second;
}

std::shared_ptr<const std::vector<double>> LoopExtraordinaryTableCache::compute(const PolygonTopology& mesh,
                                                                                const MeshConnectivity& connectivity,
                                                                                int v, int a, int b) const {
  const TriangleWalker coarse(mesh, connectivity);
  const std::vector<int> points = loop_extraordinary_neighbourhood(coarse, v, a, b);
  const int k = int(points.size()), n = mesh.n_vertices;
  // One more Loop step of the whole piece, each coarse vertex a unit vector.
  std::vector<Eigen::VectorXd> unit(size_t(n), Eigen::VectorXd::Zero(n));
  for (int i = 0; i < n; ++i) unit[size_t(i)](i) = 1.0;
  const PolygonTopology fine = loop_topology(mesh, connectivity);
  const std::vector<Eigen::VectorXd> values = loop_values(mesh, connectivity, unit, beta_);
  const MeshConnectivity fine_connectivity = connectivity_of(fine);
  const TriangleWalker walker(fine, fine_connectivity);
  const auto edge_point = [&](int x, int y) { return n + connectivity.find_edge(x, y); };
  const int ea = edge_point(v, a), eb = edge_point(v, b), eab = edge_point(a, b);
  // A: the neighbourhood of the corner child (v', e_va, e_vb) from that of (v, a, b).
  std::vector<Eigen::VectorXd> rows;
  for (const int p : loop_extraordinary_neighbourhood(walker, v, ea, eb)) rows.push_back(values[size_t(p)]);
  if (int(rows.size()) != k) throw std::logic_error("Loop extraordinary table: the neighbourhood changed size");
  const Eigen::MatrixXd step = restrict_rows(rows, points);
  // Ā_k: the nets of children 1..3 of triangle_child(), regular after one step.
  const int child[3][3] = {{ea, a, eab}, {eb, eab, b}, {eab, eb, ea}};
  Eigen::MatrixXd nets[3];
  for (int c = 0; c < 3; ++c) {
    rows.clear();
    for (const auto& combination : loop_regular_net(walker, child[c][0], child[c][1], child[c][2])) {
      Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
      for (const auto& [vertex, weight] : combination) x += weight * values[size_t(vertex)];
      rows.push_back(x);
    }
    nets[c] = restrict_rows(rows, points);
  }
  auto table = std::make_shared<std::vector<double>>(loop_extraordinary_table_size(k), 0.0);
  write_loop_extraordinary_table(nets, step, table->data());
  return table;
}

}  // namespace gps
