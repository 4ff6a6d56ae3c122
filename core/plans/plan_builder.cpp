#include "core/plans/plan_builder.h"

#include <algorithm>
#include <array>
#include <memory>
#include <stdexcept>

#include "core/mesh/element_names.h"
#include "core/support/error.h"
#include "core/patches/local_mesh.h"
#include "core/plans/plan_descent.h"
#include "core/extraordinary/quad_extraordinary_tables.h"
#include "core/patches/quad_nets.h"
#include "core/plans/range_plans.h"
#include "core/plans/stencil_table.h"

namespace gps {

namespace {

using Combo = LocalCombination;

// Exact plans of a smooth mesh refine past their depth only where a node is not yet self-similar;
// this bounds it (creased meshes go down to kMaxPlanDepth, core/plans/plan_descent.h).
constexpr int kDeepestPlan = 8;

// Builds the plans of the faces [first, last): patches in face order, stencil rows in the order of
// their first use, point indices and node offsets local to this range (merge() renumbers them).
class Builder {
public:
  Builder(const LocalMesh& base, int max_depth, ExtraordinaryNodes extraordinary, bool bspline_leaves,
          QuadExtraordinaryTableCache& cache)
      : max_depth_(max_depth),
        exact_(extraordinary == ExtraordinaryNodes::exact),
        bspline_leaves_(bspline_leaves),
        base_(base),
        cache_(cache),
        stencils_(base.topology().n_vertices) {}

  RangePlans build(int first, int last) {
    const PolygonTopology& t = base_.topology();
    for (int f = first; f < last; ++f) {
      const int n = t.face_size(f);
      if (n == 4) {
        const int* v = t.verts.data() + t.offsets[size_t(f)];
        plans_.patch_roots.push_back(build_node(base_, {v[0], v[1], v[2], v[3]}, 0, f));
        plans_.patch_corner_points.insert(plans_.patch_corner_points.end(), v, v + 4);
        for (int k = 0; k < 4; ++k) {
          const int a = v[k], b = v[(k + 1) % 4];
          add_edge(a, b, beside_split_face(f, a, b) ? PatchEdgePart::whole_beside_halves : PatchEdgePart::whole);
        }
        continue;
      }
      std::vector<int> corners(t.verts.begin() + t.offsets[size_t(f)], t.verts.begin() + t.offsets[size_t(f) + 1]);
      // A face of n sides: its n Catmull-Clark children are the patch roots, one level down already,
      // so that along an edge shared with a quad both sides reach the same depth (same limit curve).
      std::vector<int> index;
      const LocalMesh sub = extract_neighbourhood(base_, corners, index);
      const LocalMesh fine = refine_local_mesh(sub);
      const int nv = sub.topology().n_vertices, ne = sub.connectivity().n_edges();
      std::vector<int> sc(corners.size());
      for (size_t k = 0; k < corners.size(); ++k) sc[k] = index[size_t(corners[k])];
      const int face_point = nv + ne + sub.find_face(sc);
      const auto edge_point = [&](int k) { return nv + sub.find_edge(sc[size_t(k % n)], sc[size_t((k + 1) % n)]); };
      // Control-quad corners for tessellation levels: the vertex, edge midpoints and centroid of
      // the linear split, whose stencils do not depend on any summation order. Added in the order the
      // patch reads them, after its nodes (as cut_range numbers rows, core/plans/range_plans.h).
      Stencil centroid;
      for (const int c : corners) centroid += Stencil::vertex(c) * (1.0 / n);
      const auto corner = [&](int k) { return corners[size_t((k + n) % n)]; };
      for (int k = 0; k < n; ++k) {
        const std::array<int, 4> child = {sc[size_t(k)], edge_point(k), face_point, edge_point(k + n - 1)};
        plans_.patch_roots.push_back(build_node(fine, child, 1));
        const auto midpoint = [&](int a, int b) {
          return stencils_.add(Stencil::vertex(corner(a)) * 0.5 + Stencil::vertex(corner(b)) * 0.5);
        };
        const int next_mid = midpoint(k, k + 1), centroid_point = stencils_.add(centroid),
                  prev_mid = midpoint(k - 1, k);
        plans_.patch_corner_points.insert(plans_.patch_corner_points.end(),
                                          {corner(k), next_mid, centroid_point, prev_mid});
        add_edge(corner(k), corner(k + 1), PatchEdgePart::first_half);
        add_edge(next_mid, centroid_point, PatchEdgePart::whole);
        add_edge(centroid_point, prev_mid, PatchEdgePart::whole);
        add_edge(corner(k - 1), corner(k), PatchEdgePart::second_half);
      }
    }
    plans_.max_depth = deepest_;
    return {{std::move(plans_), stencils_.finish()}, std::move(extraordinary_tables_), {}, {}};
  }

private:
  void add_edge(int from, int to, PatchEdgePart part) {
    plans_.patch_edges.insert(plans_.patch_edges.end(), {from, to, int32_t(part)});
  }

  // Whether the face across base edge a–b from face f is split into patches (not a quad).
  bool beside_split_face(int f, int a, int b) const {
    const int other = other_face(base_, base_.find_edge(a, b), f);
    return other >= 0 && base_.topology().face_size(other) != 4;
  }

  int point(const LocalMesh& m, const Combo& combo) {
    if (m.is_base && combo.size() == 1 && combo[0].second == 1.0) return combo[0].first;
    return stencils_.add(m.combination(combo));
  }

  // A regular leaf's phantom points (combinations p₋₁ = 2p₀ − p₁ beyond a boundary edge) replaced
  // by the real point p₀ they mirror from; returns the boundary bits (core/patches/patch_basis.h,
  // kBoundaryV0 …), with which the basis takes them in, so the GPU sums no large differences.
  static int take_in_phantoms(std::array<Combo, 16>& net) {
    const auto phantom = [&](int i, int j) { return net[size_t(i + 4 * j)].size() != 1; };
    const bool v0 = phantom(1, 0), u1 = phantom(3, 1), v1 = phantom(1, 3), u0 = phantom(0, 1);
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) {
        const int ri = u0 && i == 0 ? 1 : u1 && i == 3 ? 2 : i, rj = v0 && j == 0 ? 1 : v1 && j == 3 ? 2 : j;
        if (ri != i || rj != j) net[size_t(i + 4 * j)] = net[size_t(ri + 4 * rj)];
      }
    return (v0 ? kBoundaryV0 : 0) | (u1 ? kBoundaryU1 : 0) | (v1 ? kBoundaryV1 : 0) | (u0 ? kBoundaryU0 : 0);
  }

  int emit_leaf(NodeKind kind, const LocalMesh& m, const std::array<Combo, 16>& net, int boundary = 0) {
    const int offset = int(plans_.nodes.size());
    plans_.nodes.push_back(int32_t(kind) | boundary << kNodeKindBits);
    for (const Combo& p : net) plans_.nodes.push_back(point(m, p));
    return offset;
  }

  // A node whose corner r is its only irregular one, evaluated exactly
  // (core/extraordinary/quad_extraordinary_tables.h), or −1 where its neighbourhood is not self-similar.
  int emit_extraordinary(const LocalMesh& m, const std::array<int, 4>& c, int r) {
    const std::array<int, 4> turned = {c[size_t(r)], c[size_t((r + 1) % 4)], c[size_t((r + 2) % 4)],
                                       c[size_t((r + 3) % 4)]};
    const auto neighbourhood = quad_extraordinary_neighbourhood(m, turned);
    if (!neighbourhood) return -1;
    auto table = cache_.table(neighbourhood->signature);
    if (!table) return -1;
    auto used = std::find(extraordinary_tables_.begin(), extraordinary_tables_.end(), table);
    if (used == extraordinary_tables_.end())
      used = extraordinary_tables_.insert(extraordinary_tables_.end(), std::move(table));
    const int offset = int(plans_.nodes.size());
    plans_.nodes.insert(plans_.nodes.end(), {kNodeExtraordinary, r, int(used - extraordinary_tables_.begin()),
                                             int(neighbourhood->points.size())});
    for (const int p : neighbourhood->points) plans_.nodes.push_back(point(m, {{p, 1.0}}));
    return offset;
  }

  // The node of the quad with corners c of m (the face `face` of m where known).
  int build_node(const LocalMesh& m, const std::array<int, 4>& c, int depth, int face = -1) {
    deepest_ = std::max(deepest_, depth);
    const int q = face >= 0 ? face : m.find_face({c[0], c[1], c[2], c[3]});
    int irregular = 0, corner = -1;
    for (int k = 0; k < 4; ++k)
      if (!regular_corner(m, c[size_t(k)], q)) ++irregular, corner = k;
    if (irregular == 0 && bspline_leaves_) {
      bspline_net(m, q, c, net_);
      const int boundary = take_in_phantoms(net_);
      return emit_leaf(NodeKind::regular, m, net_, boundary);
    }
    if (irregular == 0) return emit_leaf(NodeKind::terminal, m, bezier_net(m, c));
    if (exact_ && irregular == 1 && depth >= max_depth_ && m.complete[size_t(c[size_t(corner)])])
      if (const int offset = emit_extraordinary(m, c, corner); offset >= 0) return offset;
    if (depth == (exact_ ? deepest_allowed_ : max_depth_)) return emit_leaf(NodeKind::terminal, m, bezier_net(m, c));

    const int offset = int(plans_.nodes.size());
    plans_.nodes.insert(plans_.nodes.end(), {int32_t(NodeKind::internal), 0, 0, 0, 0});
    std::vector<int> index;
    const LocalMesh sub = extract_neighbourhood(m, {c[0], c[1], c[2], c[3]}, index);
    const LocalMesh fine = refine_local_mesh(sub);
    const int nv = sub.topology().n_vertices, ne = sub.connectivity().n_edges();
    std::array<int, 4> sc;
    for (int k = 0; k < 4; ++k) sc[size_t(k)] = index[size_t(c[size_t(k)])];
    const int face_point = nv + ne + sub.find_face({sc[0], sc[1], sc[2], sc[3]});
    int edge_point[4];
    for (int k = 0; k < 4; ++k) edge_point[k] = nv + sub.find_edge(sc[size_t(k)], sc[size_t((k + 1) % 4)]);
    // Child k = (c_k', e'_k, f', e'_{k−1}) covers the quadrant at corner k; rotate its corners so that
    // corner 0 sits at the quadrant's (0,0) and store it as child ubit + 2·vbit.
    static constexpr int kQuadrant[4] = {0, 1, 3, 2};
    for (int k = 0; k < 4; ++k) {
      const std::array<int, 4> child = {sc[size_t(k)], edge_point[k], face_point, edge_point[(k + 3) % 4]};
      std::array<int, 4> aligned;
      for (int i = 0; i < 4; ++i) aligned[size_t(i)] = child[size_t((i + 4 - k) % 4)];
      const int child_offset = build_node(fine, aligned, depth + 1);
      plans_.nodes[size_t(offset + 1 + kQuadrant[k])] = child_offset;
    }
    return offset;
  }

  int max_depth_;
  int deepest_ = 0;
  bool exact_;
  bool bspline_leaves_;
  const LocalMesh& base_;
  QuadExtraordinaryTableCache& cache_;
  // Semi-sharp creases refine their nodes until their sharpness has decayed, up to ten levels more.
  int deepest_allowed_ = base_.has_creases() ? kMaxPlanDepth : kDeepestPlan;
  std::vector<std::shared_ptr<const std::vector<double>>> extraordinary_tables_;
  std::array<Combo, 16> net_;  // the regular leaves' nets, reused (no allocation per leaf)
  StencilTableBuilder stencils_;
  PatchPlans plans_;
};

}  // namespace

namespace {
// Meshes past kMaxPlanValence are refused up front with a message.
void check_plan_valences(const PolygonTopology& t, const MeshConnectivity* c) {
  // Where the connectivity counts every vertex's faces, a mesh within the bounds is passed at once;
  // one past them is counted below, which names what a count in face order meets first.
  if (c && c->vertex_face_offsets.size() == size_t(t.n_vertices) + 1) {
    bool within = true;
    for (int f = 0; f < t.n_faces() && within; ++f) within = t.face_size(f) <= kMaxPlanValence;
    for (int v = 0; v < t.n_vertices && within; ++v) within = c->n_vertex_faces(v) <= kMaxPlanValence;
    if (within) return;
  }
  std::vector<int> faces_at(size_t(t.n_vertices), 0);
  for (int f = 0; f < t.n_faces(); ++f) {
    if (t.face_size(f) > kMaxPlanValence)
      throw ElementError(ElementError::Element::face, f, "",
                         " has " + std::to_string(t.face_size(f)) + " sides; patch plans handle up to " +
                             std::to_string(kMaxPlanValence) + " (split the face, or use gpsurf subdivide)");
    for (int k = t.offsets[size_t(f)]; k < t.offsets[size_t(f) + 1]; ++k)
      if (++faces_at[size_t(t.verts[size_t(k)])] > kMaxPlanValence)
        throw ElementError(ElementError::Element::vertex, t.verts[size_t(k)], "",
                           " has more than " + std::to_string(kMaxPlanValence) +
                               " faces; patch plans handle valences up to " + std::to_string(kMaxPlanValence) +
                               " (their stencils grow with its square; use gpsurf subdivide)");
  }
}
}  // namespace

void check_quad_plans(const PolygonTopology& topology, int max_depth, ExtraordinaryNodes extraordinary,
                      const MeshConnectivity* connectivity) {
  const int shallowest = extraordinary == ExtraordinaryNodes::exact ? 0 : 1;
  if (max_depth < shallowest || max_depth > kDeepestPlan)
    throw usage_error("plan depth must be " + std::to_string(shallowest) + "..8, got " + std::to_string(max_depth));
  check_plan_valences(topology, connectivity);
}

RangePlans build_quad_range(const LocalMesh& base, int first, int last, int max_depth, ExtraordinaryNodes extraordinary,
                            bool bspline_leaves, QuadExtraordinaryTableCache& cache) {
  return Builder(base, max_depth, extraordinary, bspline_leaves, cache).build(first, last);
}

SurfaceTables build_plans(const PolygonTopology& topology, int max_depth, ExtraordinaryNodes extraordinary,
                          bool bspline_leaves, const Sharpness& sharpness, const MeshConnectivity* connectivity) {
  check_quad_plans(topology, max_depth, extraordinary, connectivity);
  const LocalMesh base =
      connectivity ? base_local_mesh(topology, *connectivity, sharpness) : base_local_mesh(topology, sharpness);
  QuadExtraordinaryTableCache cache;
  return build_in_ranges(topology.n_faces(), topology.n_vertices, [&](int first, int last) {
    return build_quad_range(base, first, last, max_depth, extraordinary, bspline_leaves, cache);
  });
}

}  // namespace gps
