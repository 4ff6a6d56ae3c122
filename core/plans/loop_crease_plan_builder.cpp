#include "core/plans/loop_crease_plan_builder.h"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "core/extraordinary/loop_crease_tables.h"
#include "core/patches/local_mesh.h"
#include "core/patches/loop_nets.h"
#include "core/plans/plan_descent.h"
#include "core/plans/range_plans.h"
#include "core/patches/quad_nets.h"
#include "core/plans/stencil_table.h"
#include "core/patches/triangle_sectors.h"

namespace gps {

namespace {

class CreasedLoopBuilder {
public:
  CreasedLoopBuilder(const LocalMesh& base, LoopBeta beta, LoopCreaseTables& tables)
      : beta_(beta), base_(base), tables_(tables), stencils_(base.topology().n_vertices) {
    plans_.shape = PatchShape::triangle;
  }

  RangePlans build(int first, int last) {
    const PolygonTopology& t = base_.topology();
    plans_.patch_corner_points.assign(t.verts.begin() + 3 * first, t.verts.begin() + 3 * last);
    for (int f = first; f < last; ++f) {
      const int* v = &t.verts[size_t(t.offsets[size_t(f)])];
      plans_.patch_roots.push_back(build_node(base_, {v[0], v[1], v[2]}, 0, f));
    }
    plans_.max_depth = deepest_;
    return {{std::move(plans_), stencils_.finish()}, std::move(extraordinary_tables_), {}, {}};
  }

private:
  int point(const LocalMesh& m, const LocalCombination& combination) {
    if (m.is_base && combination.size() == 1 && combination[0].second == 1.0) return combination[0].first;
    return stencils_.add(m.combination(combination));
  }

  // The node of triangle x of m (the face `face` of m where known), corners in parameter order.
  int build_node(const LocalMesh& m, const std::array<int, 3>& x, int depth, int face = -1) {
    deepest_ = std::max(deepest_, depth);
    const int q = face >= 0 ? face : m.find_face({x[0], x[1], x[2]});
    int irregular = 0, corner = -1;
    for (int k = 0; k < 3; ++k)
      if (!regular_loop_corner(m, x[size_t(k)], q)) ++irregular, corner = k;
    const int offset = int(plans_.nodes.size());
    if (irregular == 0) {
      const auto net = loop_regular_net(x[0], x[1], x[2],
                                        {sector_fan(m, x[0], q), sector_fan(m, x[1], q), sector_fan(m, x[2], q)});
      plans_.nodes.push_back(kNodeRegular);
      for (const auto& p : net) plans_.nodes.push_back(point(m, {p.begin(), p.end()}));
      return offset;
    }
    if (irregular == 1 && m.complete[size_t(x[size_t(corner)])]) {
      std::vector<int> points;
      if (auto table = tables_.table(m, x[size_t(corner)], x[size_t((corner + 1) % 3)],
                                     x[size_t((corner + 2) % 3)], points)) {
        auto used = std::find(extraordinary_tables_.begin(), extraordinary_tables_.end(), table);
        if (used == extraordinary_tables_.end())
          used = extraordinary_tables_.insert(extraordinary_tables_.end(), std::move(table));
        const int index = int(used - extraordinary_tables_.begin());
        plans_.nodes.insert(plans_.nodes.end(), {kNodeExtraordinary, corner, index, int(points.size())});
        for (const int p : points) plans_.nodes.push_back(point(m, {{p, 1.0}}));
        return offset;
      }
    }
    if (depth == kMaxPlanDepth) throw std::logic_error("creased Loop plan: a node still irregular at the deepest level");
    plans_.nodes.insert(plans_.nodes.end(), {kNodeInternal, 0, 0, 0, 0});
    std::vector<int> index;
    const LocalMesh sub = extract_neighbourhood(m, {x[0], x[1], x[2]}, index);
    const LocalMesh fine = refine_local_mesh_loop(sub, beta_);
    const int nv = sub.topology().n_vertices;
    const int c0 = index[size_t(x[0])], c1 = index[size_t(x[1])], c2 = index[size_t(x[2])];
    const int e01 = nv + sub.find_edge(c0, c1), e12 = nv + sub.find_edge(c1, c2), e20 = nv + sub.find_edge(c2, c0);
    // The children of triangle_child() (core/patches/patch_basis.h), each in its own parameter order.
    const std::array<int, 3> children[4] = {{c0, e01, e20}, {e01, c1, e12}, {e20, e12, c2}, {e12, e20, e01}};
    for (int k = 0; k < 4; ++k) {
      const int child = build_node(fine, children[k], depth + 1);
      plans_.nodes[size_t(offset + 1 + k)] = child;
    }
    return offset;
  }

  LoopBeta beta_;
  const LocalMesh& base_;
  LoopCreaseTables& tables_;
  std::vector<std::shared_ptr<const std::vector<double>>> extraordinary_tables_;
  StencilTableBuilder stencils_;
  PatchPlans plans_;
  int deepest_ = 0;
};

}  // namespace

RangePlans build_creased_loop_range(const LocalMesh& base, int first, int last, LoopBeta beta,
                                    LoopCreaseTables& tables) {
  return CreasedLoopBuilder(base, beta, tables).build(first, last);
}

SurfaceTables build_creased_loop_plans(const PolygonTopology& topology, LoopBeta beta, const Sharpness& sharpness,
                                       const MeshConnectivity* connectivity) {
  const LocalMesh base =
      connectivity ? base_local_mesh(topology, *connectivity, sharpness) : base_local_mesh(topology, sharpness);
  LoopCreaseTables tables(beta);
  return build_in_ranges(topology.n_faces(), topology.n_vertices, [&](int first, int last) {
    return build_creased_loop_range(base, first, last, beta, tables);
  });
}

}  // namespace gps
