#include "core/extraordinary/loop_crease_tables.h"

#include "core/extraordinary/loop_extraordinary_tables.h"
#include "core/extraordinary/neighbourhood_signature.h"
#include "core/patches/loop_nets.h"
#include "core/patches/patch_basis.h"
#include "core/patches/triangle_sectors.h"

namespace gps {

std::shared_ptr<const std::vector<double>> LoopCreaseTables::table(const LocalMesh& m, int v, int a, int b,
                                                                  std::vector<int>& points) {
  const auto neighbourhood = neighbourhood_signature(m, {v, a, b});
  if (!neighbourhood) return nullptr;
  points = neighbourhood->points;
  {
    const std::lock_guard lock(mutex_);
    if (const auto it = tables_.find(neighbourhood->signature); it != tables_.end()) return it->second;
  }
  auto computed = compute(neighbourhood->signature);  // outside the lock: threads meeting other signatures go on
  const std::lock_guard lock(mutex_);
  return tables_.try_emplace(neighbourhood->signature, std::move(computed)).first->second;
}

std::shared_ptr<const std::vector<double>> LoopCreaseTables::compute(const std::vector<int>& signature) const {
  const LocalMesh coarse = neighbourhood_mesh(signature, 3);
  const LocalMesh fine = refine_local_mesh_loop(coarse, beta_);
  const int k = coarse.topology().n_vertices;
  const auto edge_point = [&](int x, int y) { return k + coarse.find_edge(x, y); };
  const int ea = edge_point(0, 1), eb = edge_point(0, 2), eab = edge_point(1, 2);
  // A: the corner child (v', e_va, e_vb) must have the same neighbourhood, one level down.
  const auto child = neighbourhood_signature(fine, {0, ea, eb});
  if (!child || child->signature != signature) return nullptr;
  std::vector<LocalCombination> step_rows;
  for (const int p : child->points) step_rows.push_back({{p, 1.0}});
  const Eigen::MatrixXd step = rows_over_neighbourhood(fine, step_rows, k);
  // Ā_k: the nets of children 1..3 of triangle_child() (core/patches/patch_basis.h).
  const std::array<int, 3> children[3] = {{ea, 1, eab}, {eb, eab, 2}, {eab, eb, ea}};
  Eigen::MatrixXd nets[3];
  for (int c = 0; c < 3; ++c) {
    const auto& x = children[c];
    const int face = fine.find_face({x[0], x[1], x[2]});
    for (const int corner : x)
      if (!regular_loop_corner(fine, corner, face)) return nullptr;
    const auto net = loop_regular_net(x[0], x[1], x[2],
                                      {sector_fan(fine, x[0], face), sector_fan(fine, x[1], face), sector_fan(fine, x[2], face)});
    std::vector<LocalCombination> rows;
    for (const auto& combination : net) rows.emplace_back(combination.begin(), combination.end());
    nets[c] = rows_over_neighbourhood(fine, rows, k);
  }
  auto table = std::make_shared<std::vector<double>>(loop_extraordinary_table_size(k), 0.0);
  write_loop_extraordinary_table(nets, step, table->data());
  return table;
}

}  // namespace gps
