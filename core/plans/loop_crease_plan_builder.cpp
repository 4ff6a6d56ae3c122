#include "core/plans/loop_crease_plan_builder.h"

#include <array>
#include <stdexcept>

#include "core/extraordinary/loop_crease_tables.h"
#include "core/plans/local_mesh.h"
#include "core/plans/loop_nets.h"
#include "core/plans/plan_descent.h"
#include "core/plans/quad_nets.h"
#include "core/plans/stencil_table.h"
#include "core/plans/triangle_sectors.h"

namespace gps {

namespace {

class CreasedLoopBuilder {
public:
  CreasedLoopBuilder(const PolygonTopology& t, LoopBeta beta, const Sharpness& sharpness)
      : beta_(beta), base_(base_local_mesh(t, sharpness)), tables_(beta), stencils_(t.n_vertices) {
    plans_.shape = PatchShape::triangle;
  }

  SurfaceTables build() {
    const PolygonTopology& t = base_.topology;
    plans_.patch_corner_points = t.verts;
    for (int f = 0; f < t.n_faces(); ++f) {
      const int* v = &t.verts[size_t(t.offsets[size_t(f)])];
      plans_.patch_roots.push_back(build_node(base_, {v[0], v[1], v[2]}, 0, f));
    }
    plans_.max_depth = deepest_;
    plans_.extraordinary_tables = tables_.take();
    return {std::move(plans_), stencils_.finish()};
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
      const int table = tables_.offset(m, x[size_t(corner)], x[size_t((corner + 1) % 3)], x[size_t((corner + 2) % 3)],
                                       points);
      if (table >= 0) {
        plans_.nodes.insert(plans_.nodes.end(), {kNodeExtraordinary, corner, table, int(points.size())});
        for (const int p : points) plans_.nodes.push_back(point(m, {{p, 1.0}}));
        return offset;
      }
    }
    if (depth == kMaxPlanDepth) throw std::logic_error("creased Loop plan: a node still irregular at the deepest level");
    plans_.nodes.insert(plans_.nodes.end(), {kNodeInternal, 0, 0, 0, 0});
    std::vector<int> index;
    const LocalMesh sub = extract_neighbourhood(m, {x[0], x[1], x[2]}, index);
    const LocalMesh fine = refine_local_mesh_loop(sub, beta_);
    const int nv = sub.topology.n_vertices;
    const int c0 = index[size_t(x[0])], c1 = index[size_t(x[1])], c2 = index[size_t(x[2])];
    const int e01 = nv + sub.find_edge(c0, c1), e12 = nv + sub.find_edge(c1, c2), e20 = nv + sub.find_edge(c2, c0);
    // The children of triangle_child() (core/plans/patch_basis.h), each in its own parameter order.
    const std::array<int, 3> children[4] = {{c0, e01, e20}, {e01, c1, e12}, {e20, e12, c2}, {e12, e20, e01}};
    for (int k = 0; k < 4; ++k) {
      const int child = build_node(fine, children[k], depth + 1);
      plans_.nodes[size_t(offset + 1 + k)] = child;
    }
    return offset;
  }

  LoopBeta beta_;
  LocalMesh base_;
  LoopCreaseTables tables_;
  StencilTableBuilder stencils_;
  PatchPlans plans_;
  int deepest_ = 0;
};

}  // namespace

SurfaceTables build_creased_loop_plans(const PolygonTopology& topology, LoopBeta beta, const Sharpness& sharpness) {
  return CreasedLoopBuilder(topology, beta, sharpness).build();
}

}  // namespace gps
