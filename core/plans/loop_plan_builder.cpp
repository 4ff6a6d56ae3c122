#include "core/plans/loop_plan_builder.h"

#include <Eigen/Core>
#include <algorithm>
#include <map>
#include <unordered_map>

#include "core/mesh/element_names.h"
#include "core/support/error.h"
#include "core/extraordinary/loop_extraordinary_tables.h"
#include "core/plans/loop_crease_plan_builder.h"
#include "core/patches/loop_nets.h"
#include "core/plans/range_plans.h"
#include "core/plans/stencil_table.h"

namespace gps {

namespace {

// Throws gps::Error naming the first face that is not a triangle or vertex of too many faces.
void check_loop_mesh(const PolygonTopology& t, const MeshConnectivity& c) {
  for (int f = 0; f < t.n_faces(); ++f)
    if (t.face_size(f) != 3)
      throw ElementError(ElementError::Element::face, f, "Loop patches need a triangle mesh, but ",
                         " has " + std::to_string(t.face_size(f)) + " vertices");
  for (int v = 0; v < t.n_vertices; ++v)
    if (c.n_vertex_faces(v) > kMaxLoopValence)
      throw ElementError(ElementError::Element::vertex, v, "",
                         " has " + std::to_string(c.n_vertex_faces(v)) + " faces; Loop patches take at most " +
                             std::to_string(kMaxLoopValence) + " (use --scheme catmull-clark)");
}

// The plans of a run of faces of a triangle mesh that passed check_loop_mesh.
class LoopRangeBuilder {
public:
  LoopRangeBuilder(const PolygonTopology& t, const MeshConnectivity& c, LoopBeta beta,
                   LoopExtraordinaryTableCache& tables)
      : t_(t), c_(c), beta_(beta), tables_(tables), stencils_(t.n_vertices) {
    plans_.shape = PatchShape::triangle;
  }

  RangePlans build(int first, int last) {
    plans_.patch_roots.reserve(size_t(last - first));
    plans_.patch_corner_points.assign(t_.verts.begin() + 3 * first, t_.verts.begin() + 3 * last);
    plans_.nodes.reserve(size_t(last - first) * 13);
    for (int f = first; f < last; ++f) {
      const int* v = &t_.verts[size_t(t_.offsets[size_t(f)])];
      if (loop_regular_vertex(c_, v[0]) && loop_regular_vertex(c_, v[1]) && loop_regular_vertex(c_, v[2]))
        plans_.patch_roots.push_back(
            emit_regular(loop_regular_net(v[0], v[1], v[2], {fan(v[0]), fan(v[1]), fan(v[2])}), nullptr));
      else
        plans_.patch_roots.push_back(build_split(f));
    }
    return {{std::move(plans_), stencils_.finish()}, std::move(extraordinary_tables_), {}, {}};
  }

private:
  // v's fan (triangle_fan), found once per range: a vertex is a corner of about six of its faces.
  const std::vector<int>& fan(int v) {
    const auto [at, added] = fans_.try_emplace(v);
    if (added) at->second = triangle_fan(t_, c_, v);
    return at->second;
  }

  // The stencils of a piece's vertices over the base vertices: per piece vertex, weights over `base`.
  struct Piece {
    std::vector<int> base;                 // piece-local coarse index → base vertex
    std::vector<Eigen::VectorXd> weights;  // per fine vertex: weights over `base`
  };

  int point(const VertexCombination& combination, const Piece* piece) {
    if (!piece) {
      if (combination.size() == 1 && combination[0].second == 1.0) return combination[0].first;
      std::map<int, double> terms;
      for (const auto& [v, w] : combination) terms[v] += w;
      return stencils_.add(Stencil::from_terms({terms.begin(), terms.end()}));
    }
    Eigen::VectorXd x = Eigen::VectorXd::Zero(long(piece->base.size()));
    for (const auto& [v, w] : combination) x += w * piece->weights[size_t(v)];
    std::vector<std::pair<int, double>> terms;
    for (long i = 0; i < x.size(); ++i)
      if (x(i) != 0.0) terms.emplace_back(piece->base[size_t(i)], x(i));
    std::sort(terms.begin(), terms.end());
    return stencils_.add(Stencil::from_terms(std::move(terms)));
  }

  int emit_regular(const std::array<VertexCombination, 12>& net, const Piece* piece) {
    const int offset = int(plans_.nodes.size());
    plans_.nodes.push_back(kNodeRegular);
    for (const auto& p : net) plans_.nodes.push_back(point(p, piece));
    return offset;
  }

  // The configuration of base vertex v as seen from face f.
  LoopExtraordinaryConfiguration configuration(int v, int f) const {
    LoopExtraordinaryConfiguration k;
    k.faces = c_.n_vertex_faces(v);
    if (vertex_role(c_, v) == VertexRole::interior) return k;
    k.boundary = true;
    // Fan position: count faces clockwise from f to the boundary.
    const int o = t_.offsets[size_t(f)];
    int corner = 0;
    while (t_.verts[size_t(o + corner)] != v) ++corner;
    for (int w = t_.verts[size_t(o + (corner + 1) % 3)]; (w = cw_next(t_, c_, v, w)) >= 0;) ++k.fan_position;
    return k;
  }

  // A triangle with an irregular corner: one Loop step of the faces around its corners. Its node comes
  // first, then its children's, as the other builders lay them out.
  int build_split(int f) {
    const int* v = &t_.verts[size_t(t_.offsets[size_t(f)])];
    const int offset = int(plans_.nodes.size());
    plans_.nodes.insert(plans_.nodes.end(), {kNodeInternal, 0, 0, 0, 0});
    plans_.max_depth = 1;
    // The piece: every face around the three corners, renumbered.
    std::vector<int> faces;
    for (int k = 0; k < 3; ++k)
      for (int i = c_.vertex_face_offsets[size_t(v[k])]; i < c_.vertex_face_offsets[size_t(v[k]) + 1]; ++i)
        faces.push_back(c_.vertex_faces[size_t(i)]);
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    Piece piece;
    std::map<int, int> local;
    PolygonTopology coarse;
    for (const int g : faces)
      for (int k = 0; k < 3; ++k) {
        const int x = t_.verts[size_t(t_.offsets[size_t(g)] + k)];
        const auto [it, added] = local.try_emplace(x, int(piece.base.size()));
        if (added) piece.base.push_back(x);
        coarse.verts.push_back(it->second);
        if (k == 2) coarse.offsets.push_back(int(coarse.verts.size()));
      }
    coarse.n_vertices = int(piece.base.size());
    const MeshConnectivity coarse_connectivity = connectivity_of(coarse);
    std::vector<Eigen::VectorXd> unit(piece.base.size(), Eigen::VectorXd::Zero(long(piece.base.size())));
    for (size_t i = 0; i < unit.size(); ++i) unit[i](long(i)) = 1.0;
    // Exact where the piece holds every face around a vertex or edge: the corners and their edges.
    piece.weights = loop_values(coarse, coarse_connectivity, unit, beta_);
    const PolygonTopology fine = loop_topology(coarse, coarse_connectivity);
    const MeshConnectivity fine_connectivity = connectivity_of(fine);
    const TriangleWalker walker(fine, fine_connectivity);
    const int n = coarse.n_vertices;
    const int c[3] = {local[v[0]], local[v[1]], local[v[2]]};
    const int e01 = n + coarse_connectivity.find_edge(c[0], c[1]), e12 = n + coarse_connectivity.find_edge(c[1], c[2]),
              e20 = n + coarse_connectivity.find_edge(c[2], c[0]);
    const int child[4][3] = {{c[0], e01, e20}, {e01, c[1], e12}, {e20, e12, c[2]}, {e12, e20, e01}};
    for (int k = 0; k < 4; ++k) {
      const int* x = child[k];
      int node = int(plans_.nodes.size());
      if (k < 3 && !loop_regular_vertex(c_, v[k])) {
        // Child k holds base corner k at its own corner k: turn it to corner 0.
        const int a = x[(k + 1) % 3], b = x[(k + 2) % 3];
        const int table = table_index(tables_.table(configuration(v[k], f), fine, fine_connectivity, c[k], a, b));
        const std::vector<int> points = loop_extraordinary_neighbourhood(walker, c[k], a, b);
        plans_.nodes.insert(plans_.nodes.end(), {kNodeExtraordinary, k, table, int(points.size())});
        for (const int p : points) plans_.nodes.push_back(point({{p, 1.0}}, &piece));
      } else {
        node = emit_regular(loop_regular_net(walker, x[0], x[1], x[2]), &piece);
      }
      plans_.nodes[size_t(offset + 1 + k)] = node;
    }
    return offset;
  }

  // The range's index of `table`, added on first use.
  int table_index(std::shared_ptr<const std::vector<double>> table) {
    auto used = std::find(extraordinary_tables_.begin(), extraordinary_tables_.end(), table);
    if (used == extraordinary_tables_.end())
      used = extraordinary_tables_.insert(extraordinary_tables_.end(), std::move(table));
    return int(used - extraordinary_tables_.begin());
  }

  const PolygonTopology& t_;
  const MeshConnectivity& c_;
  LoopBeta beta_;
  LoopExtraordinaryTableCache& tables_;
  std::vector<std::shared_ptr<const std::vector<double>>> extraordinary_tables_;
  std::unordered_map<int, std::vector<int>> fans_;  // per base vertex met: its fan
  StencilTableBuilder stencils_;
  PatchPlans plans_;
};

}  // namespace

void check_loop_plans(const PolygonTopology& topology, const MeshConnectivity* connectivity) {
  if (connectivity) return check_loop_mesh(topology, *connectivity);
  check_loop_mesh(topology, connectivity_of(topology));
}

RangePlans build_loop_range(const PolygonTopology& topology, const MeshConnectivity& connectivity, int first, int last,
                            LoopBeta beta, LoopExtraordinaryTableCache& tables) {
  return LoopRangeBuilder(topology, connectivity, beta, tables).build(first, last);
}

SurfaceTables build_loop_plans(const PolygonTopology& topology, LoopBeta beta, const Sharpness& sharpness,
                               const MeshConnectivity* connectivity) {
  const MeshConnectivity built = connectivity ? MeshConnectivity{} : connectivity_of(topology);
  const MeshConnectivity& c = connectivity ? *connectivity : built;
  check_loop_mesh(topology, c);
  Sharpness sharp = sharpness;
  sharp.normalise();
  if (!sharp.empty()) return build_creased_loop_plans(topology, beta, sharp, &c);
  LoopExtraordinaryTableCache tables(beta);
  return build_in_ranges(topology.n_faces(), topology.n_vertices,
                         [&](int first, int last) { return build_loop_range(topology, c, first, last, beta, tables); });
}

}  // namespace gps
