#include "core/plan_builder.h"

#include <algorithm>
#include <array>
#include <exception>
#include <stdexcept>

#include "core/error.h"
#include "core/limit_masks.h"
#include "core/local_mesh.h"
#include "core/stencil_table.h"

namespace gps {

namespace {

// A point as a combination of the vertices of a LocalMesh (before it becomes a base stencil).
using Combo = std::vector<std::pair<int, double>>;

Combo one(int v) { return {{v, 1.0}}; }

Combo combine(const std::vector<std::pair<const Combo*, double>>& parts) {
  Combo out;
  for (const auto& [c, w] : parts)
    for (const auto& [v, x] : *c) out.emplace_back(v, w * x);
  return out;
}

struct Grid2 {
  int i, j;
  Grid2 operator+(Grid2 o) const { return {i + o.i, j + o.j}; }
  Grid2 operator-(Grid2 o) const { return {i - o.i, j - o.j}; }
};

// Corner k of a node's quad sits at grid position kCorner[k] of its 4×4 B-spline net; kOut[k] points
// away from the quad across edge k (from corner k to corner k+1).
constexpr Grid2 kCorner[4] = {{1, 1}, {2, 1}, {2, 2}, {1, 2}};
constexpr Grid2 kOut[4] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};

int face_vertex(const LocalMesh& m, int f, int k) {
  const int n = m.topology.face_size(f);
  return m.topology.verts[size_t(m.topology.offsets[size_t(f)] + ((k % n) + n) % n)];
}

int corner_index(const LocalMesh& m, int f, int v) {
  for (int k = 0; k < m.topology.face_size(f); ++k)
    if (face_vertex(m, f, k) == v) return k;
  throw std::logic_error("plan builder: vertex not in face");
}

int other_face(const LocalMesh& m, int e, int f) {
  const int a = m.connectivity.edge_faces[2 * size_t(e)], b = m.connectivity.edge_faces[2 * size_t(e) + 1];
  return a == f ? b : a;
}

// Builds the plans of the faces [first, last): patches in face order, stencil rows in the order of
// their first use, point indices and node offsets local to this range (merge() renumbers them).
class Builder {
public:
  Builder(const LocalMesh& base, int max_depth, bool bspline_leaves)
      : max_depth_(max_depth), bspline_leaves_(bspline_leaves), base_(base), stencils_(base.topology.n_vertices) {}

  PlanTables build(int first, int last) {
    const PolygonTopology& t = base_.topology;
    for (int f = first; f < last; ++f) {
      std::vector<int> corners(t.verts.begin() + t.offsets[size_t(f)], t.verts.begin() + t.offsets[size_t(f) + 1]);
      const int n = int(corners.size());
      if (n == 4) {
        plans_.patch_roots.push_back(build_node(base_, {corners[0], corners[1], corners[2], corners[3]}, 0));
        plans_.patch_corner_points.insert(plans_.patch_corner_points.end(), corners.begin(), corners.end());
        for (int k = 0; k < 4; ++k) {
          const int a = corners[size_t(k)], b = corners[size_t((k + 1) % 4)];
          add_edge(a, b, beside_split_face(f, a, b) ? PatchEdgePart::whole_beside_halves : PatchEdgePart::whole);
        }
        continue;
      }
      // A face of n sides: its n Catmull-Clark children are the patch roots, one level down already,
      // so that along an edge shared with a quad both sides reach the same depth (same limit curve).
      std::vector<int> index;
      const LocalMesh sub = extract_neighbourhood(base_, corners, index);
      const LocalMesh fine = refine_local_mesh(sub);
      const int nv = sub.topology.n_vertices, ne = sub.connectivity.n_edges();
      std::vector<int> sc(corners.size());
      for (size_t k = 0; k < corners.size(); ++k) sc[k] = index[size_t(corners[k])];
      const int face_point = nv + ne + sub.find_face(sc);
      const auto edge_point = [&](int k) { return nv + sub.find_edge(sc[size_t(k % n)], sc[size_t((k + 1) % n)]); };
      // Control-quad corners for tessellation levels: the vertex, edge midpoints and centroid of
      // the linear split, whose stencils do not depend on any summation order.
      Stencil centroid;
      for (const int c : corners) centroid += Stencil::vertex(c) * (1.0 / n);
      const int centroid_point = stencils_.add(centroid);
      const auto corner = [&](int k) { return corners[size_t((k + n) % n)]; };
      for (int k = 0; k < n; ++k) {
        const std::array<int, 4> child = {sc[size_t(k)], edge_point(k), face_point, edge_point(k + n - 1)};
        plans_.patch_roots.push_back(build_node(fine, child, 1));
        const auto midpoint = [&](int a, int b) {
          return stencils_.add(Stencil::vertex(corner(a)) * 0.5 + Stencil::vertex(corner(b)) * 0.5);
        };
        const int next_mid = midpoint(k, k + 1), prev_mid = midpoint(k - 1, k);
        plans_.patch_corner_points.insert(plans_.patch_corner_points.end(), {corner(k), next_mid, centroid_point, prev_mid});
        add_edge(corner(k), corner(k + 1), PatchEdgePart::first_half);
        add_edge(next_mid, centroid_point, PatchEdgePart::whole);
        add_edge(centroid_point, prev_mid, PatchEdgePart::whole);
        add_edge(corner(k - 1), corner(k), PatchEdgePart::second_half);
      }
    }
    plans_.max_depth = max_depth_;
    return {std::move(plans_), stencils_.finish()};
  }

private:
  void add_edge(int from, int to, PatchEdgePart part) {
    plans_.patch_edges.insert(plans_.patch_edges.end(), {from, to, int32_t(part)});
  }

  // Whether the face across base edge a–b from face f is split into patches (not a quad).
  bool beside_split_face(int f, int a, int b) const {
    const int other = other_face(base_, base_.find_edge(a, b), f);
    return other >= 0 && base_.topology.face_size(other) != 4;
  }

  int point(const LocalMesh& m, const Combo& combo) {
    if (m.is_base && combo.size() == 1 && combo[0].second == 1.0) return combo[0].first;
    return stencils_.add(m.combination(combo));
  }

  // Interior valence 4, boundary with two faces, or a corner with one face; all faces around quads.
  static bool regular_vertex(const LocalMesh& m, int v) {
    const auto& c = m.connectivity;
    if (!m.complete[size_t(v)]) return false;
    for (int i = c.vertex_face_offsets[size_t(v)]; i < c.vertex_face_offsets[size_t(v) + 1]; ++i)
      if (m.topology.face_size(c.vertex_faces[size_t(i)]) != 4) return false;
    switch (vertex_role(c, v)) {
      case VertexRole::interior: return c.n_vertex_faces(v) == 4;
      case VertexRole::boundary: return c.n_vertex_faces(v) == 2;
      case VertexRole::corner: return true;
      case VertexRole::isolated: return false;
    }
    return false;
  }

  // The 4×4 B-spline net of a regular quad, with boundary phantoms p₋₁ = 2p₀ − p₁.
  std::array<Combo, 16> bspline_net(const LocalMesh& m, int q, const std::array<int, 4>& c) {
    std::array<Combo, 16> net;
    const auto at = [&](Grid2 g) -> Combo& { return net[size_t(g.i + 4 * g.j)]; };
    const auto mirror = [&](Grid2 g, Grid2 out) { at(g + out) = combine({{&at(g), 2.0}, {&at(g - out), -1.0}}); };
    bool boundary_edge[4];
    for (int k = 0; k < 4; ++k) at(kCorner[k]) = one(c[size_t(k)]);
    for (int k = 0; k < 4; ++k) {
      const int a = c[size_t(k)], b = c[size_t((k + 1) % 4)];
      const int e = m.find_edge(a, b);
      boundary_edge[k] = m.connectivity.is_boundary_edge(e);
      if (boundary_edge[k]) {
        mirror(kCorner[k], kOut[k]);
        mirror(kCorner[(k + 1) % 4], kOut[k]);
        continue;
      }
      const int n = other_face(m, e, q), j = corner_index(m, n, a);  // n runs b, a, x, y
      at(kCorner[k] + kOut[k]) = one(face_vertex(m, n, j + 1));
      at(kCorner[(k + 1) % 4] + kOut[k]) = one(face_vertex(m, n, j + 2));
    }
    for (int k = 0; k < 4; ++k) {
      const Grid2 g = kCorner[k], o1 = kOut[k], o2 = kOut[(k + 3) % 4];
      const int v = c[size_t(k)];
      if (vertex_role(m.connectivity, v) == VertexRole::interior) {
        const auto& conn = m.connectivity;
        for (int i = conn.vertex_face_offsets[size_t(v)]; i < conn.vertex_face_offsets[size_t(v) + 1]; ++i) {
          const int f = conn.vertex_faces[size_t(i)], kv = conn.vertex_face_corners[size_t(i)];
          const int prev = face_vertex(m, f, kv + 3), next = face_vertex(m, f, kv + 1);
          if (f == q || prev == c[size_t((k + 1) % 4)] || next == c[size_t((k + 1) % 4)] || prev == c[size_t((k + 3) % 4)] ||
              next == c[size_t((k + 3) % 4)])
            continue;
          at(g + o1 + o2) = one(face_vertex(m, f, kv + 2));
        }
      } else if (boundary_edge[(k + 3) % 4]) {
        mirror(g + o1, o2);
      } else {
        mirror(g + o2, o1);
      }
    }
    return net;
  }

  // The Bézier net of a terminal node by the rules of thesis Fig. 2.5 (DESIGN.md §2).
  std::array<Combo, 16> bezier_net(const LocalMesh& m, const std::array<int, 4>& c) {
    static constexpr Grid2 kBezier[4] = {{0, 0}, {3, 0}, {3, 3}, {0, 3}};
    const auto& conn = m.connectivity;
    std::array<Combo, 16> net;
    const auto at = [&](Grid2 g) -> Combo& { return net[size_t(g.i + 4 * g.j)]; };
    for (int k = 0; k < 4; ++k) {
      const int v = c[size_t(k)], next = c[size_t((k + 1) % 4)], prev = c[size_t((k + 3) % 4)], opposite = c[size_t((k + 2) % 4)];
      const VertexRole role = vertex_role(conn, v);
      const int n = conn.valence(v);
      const double nr = role == VertexRole::interior ? n : 4.0;  // boundary vertices take regular weights
      const Grid2 g = kBezier[k];
      const Grid2 to_next = {(kBezier[(k + 1) % 4].i - g.i) / 3, (kBezier[(k + 1) % 4].j - g.j) / 3};
      const Grid2 to_prev = {(kBezier[(k + 3) % 4].i - g.i) / 3, (kBezier[(k + 3) % 4].j - g.j) / 3};
      // Corner point: the exact limit position.
      Combo corner;
      if (role == VertexRole::interior) {
        const double total = n * (n + 5.0);
        corner.emplace_back(v, n * n / total);
        for (int i = conn.vertex_edge_offsets[size_t(v)]; i < conn.vertex_edge_offsets[size_t(v) + 1]; ++i)
          corner.emplace_back(conn.other_vertex(conn.vertex_edges[size_t(i)], v), 4.0 / total);
        for (int i = conn.vertex_face_offsets[size_t(v)]; i < conn.vertex_face_offsets[size_t(v) + 1]; ++i)
          corner.emplace_back(face_vertex(m, conn.vertex_faces[size_t(i)], conn.vertex_face_corners[size_t(i)] + 2), 1.0 / total);
      } else if (role == VertexRole::boundary) {
        int a = -1, b = -1;
        vertex_role(conn, v, &a, &b);
        corner = {{a, 1.0 / 6.0}, {v, 4.0 / 6.0}, {b, 1.0 / 6.0}};
      } else {
        corner = one(v);
      }
      at(g) = corner;
      // Edge points on the edges to `next` and `prev`.
      for (const auto& [w, dir] : {std::pair{next, to_next}, std::pair{prev, to_prev}}) {
        const int e = m.find_edge(v, w);
        if (conn.is_boundary_edge(e)) {
          at(g + dir) = {{v, 2.0 / 3.0}, {w, 1.0 / 3.0}};
          continue;
        }
        const double total = 2.0 * nr + 10.0;
        Combo edge = {{v, 2.0 * nr / total}, {w, 4.0 / total}};
        for (const int f : {conn.edge_faces[2 * size_t(e)], conn.edge_faces[2 * size_t(e) + 1]}) {
          const int kv = corner_index(m, f, v), kw = corner_index(m, f, w);
          const int beside_v = face_vertex(m, f, kv + (face_vertex(m, f, kv + 1) == w ? 3 : 1));
          const int beside_w = face_vertex(m, f, kw + (face_vertex(m, f, kw + 1) == v ? 3 : 1));
          edge.emplace_back(beside_v, 2.0 / total);
          edge.emplace_back(beside_w, 1.0 / total);
        }
        at(g + dir) = edge;
      }
      // Interior point.
      const double total = nr + 5.0;
      at(g + to_next + to_prev) = {{v, nr / total}, {next, 2.0 / total}, {prev, 2.0 / total}, {opposite, 1.0 / total}};
    }
    return net;
  }

  int emit_leaf(NodeKind kind, const LocalMesh& m, const std::array<Combo, 16>& net) {
    const int offset = int(plans_.nodes.size());
    plans_.nodes.push_back(int32_t(kind));
    for (const Combo& p : net) plans_.nodes.push_back(point(m, p));
    return offset;
  }

  int build_node(const LocalMesh& m, const std::array<int, 4>& c, int depth) {
    bool regular = true;
    for (const int v : c) regular = regular && regular_vertex(m, v);
    const std::vector<int> corners(c.begin(), c.end());
    if (regular && bspline_leaves_) return emit_leaf(NodeKind::regular, m, bspline_net(m, m.find_face(corners), c));
    if (regular) return emit_leaf(NodeKind::terminal, m, bezier_net(m, c));
    if (depth == max_depth_) return emit_leaf(NodeKind::terminal, m, bezier_net(m, c));

    const int offset = int(plans_.nodes.size());
    plans_.nodes.insert(plans_.nodes.end(), {int32_t(NodeKind::internal), 0, 0, 0, 0});
    std::vector<int> index;
    const LocalMesh sub = extract_neighbourhood(m, corners, index);
    const LocalMesh fine = refine_local_mesh(sub);
    const int nv = sub.topology.n_vertices, ne = sub.connectivity.n_edges();
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
  bool bspline_leaves_;
  const LocalMesh& base_;
  StencilTableBuilder stencils_;
  PlanTable plans_;
};

// Appends the plans of consecutive face ranges in order. A row is added to the whole table where it
// is first used, which is in the first range that uses it, in that range's order: so the result is
// the table a single range over all faces gives, bit for bit, whatever the ranges. The rows are
// merged in order, one range after the other; the renumbered nodes are then copied on all cores.
PlanTables merge(std::vector<PlanTables>& parts, int n_base) {
  StencilTableBuilder stencils(n_base);
  std::vector<std::vector<int>> rows(parts.size());  // per range: local row -> point in the whole table
  for (size_t r = 0; r < parts.size(); ++r) {
    const StencilTable& s = parts[r].stencils;
    rows[r].resize(size_t(s.n_rows()));
    for (int row = 0; row < s.n_rows(); ++row) rows[r][size_t(row)] = stencils.add_row(s, row);
  }
  // Where each range's records start in the whole table.
  std::vector<size_t> node_base(parts.size() + 1, 0), patch_base(parts.size() + 1, 0);
  for (size_t r = 0; r < parts.size(); ++r) {
    node_base[r + 1] = node_base[r] + parts[r].plans.nodes.size();
    patch_base[r + 1] = patch_base[r] + parts[r].plans.patch_roots.size();
  }
  PlanTable plans;
  plans.nodes.resize(node_base.back());
  plans.patch_roots.resize(patch_base.back());
  plans.patch_corner_points.resize(4 * patch_base.back());
  plans.patch_edges.resize(12 * patch_base.back());
#pragma omp parallel for schedule(dynamic)
  for (size_t r = 0; r < parts.size(); ++r) {
    const PlanTable& p = parts[r].plans;
    const auto point = [&row = rows[r], n_base](int p) { return p < n_base ? p : row[size_t(p - n_base)]; };
    const int base = int(node_base[r]);
    int32_t* nodes = plans.nodes.data() + node_base[r];
    for (size_t o = 0; o < p.nodes.size();) {  // node records: kind, then 4 child offsets or 16 points
      const auto kind = NodeKind(p.nodes[o]);
      nodes[o] = p.nodes[o];
      const size_t n = kind == NodeKind::internal ? 4 : 16;
      for (size_t i = o + 1; i <= o + n; ++i) nodes[i] = kind == NodeKind::internal ? base + p.nodes[i] : point(p.nodes[i]);
      o += n + 1;
    }
    const size_t first = patch_base[r];
    for (size_t i = 0; i < p.patch_roots.size(); ++i) plans.patch_roots[first + i] = base + p.patch_roots[i];
    for (size_t i = 0; i < p.patch_corner_points.size(); ++i) plans.patch_corner_points[4 * first + i] = point(p.patch_corner_points[i]);
    for (size_t i = 0; i < p.patch_edges.size(); ++i)
      plans.patch_edges[12 * first + i] = i % 3 == 2 ? p.patch_edges[i] : point(p.patch_edges[i]);
    parts[r] = {};
  }
  return {std::move(plans), stencils.finish()};
}

}  // namespace

namespace {
// The plans read every neighbour of an extraordinary vertex from each patch at it (thesis Fig. 2.5
// corner rule), so their stencils grow with the square of the valence (and of the face size, which
// becomes the valence of the face's centre after the split): past this bound they would take
// minutes and gigabytes, so such meshes are refused up front with a message.
constexpr int kMaxPlanValence = 256;

void check_plan_valences(const PolygonTopology& t) {
  std::vector<int> faces_at(size_t(t.n_vertices), 0);
  for (int f = 0; f < t.n_faces(); ++f) {
    if (t.face_size(f) > kMaxPlanValence)
      throw Error("face " + std::to_string(f) + " has " + std::to_string(t.face_size(f)) + " sides; patch plans handle up to " +
                  std::to_string(kMaxPlanValence) + " (split the face, or use gpsurf subdivide)");
    for (int k = t.offsets[size_t(f)]; k < t.offsets[size_t(f) + 1]; ++k)
      if (++faces_at[size_t(t.verts[size_t(k)])] > kMaxPlanValence)
        throw Error("vertex " + std::to_string(t.verts[size_t(k)]) + " has more than " + std::to_string(kMaxPlanValence) +
                    " faces; patch plans handle valences up to " + std::to_string(kMaxPlanValence) +
                    " (their stencils grow with its square; use gpsurf subdivide)");
  }
}
}  // namespace

PlanTables build_plans(const PolygonTopology& topology, int max_depth, bool bspline_leaves) {
  if (max_depth < 1 || max_depth > 8) throw usage_error("plan depth must be 1..8, got " + std::to_string(max_depth));
  check_plan_valences(topology);
  const LocalMesh base = base_local_mesh(topology);
  // Faces in ranges of a fixed size, built on all cores (OpenMP), merged in order.
  constexpr int kFacesPerRange = 1024;
  const int n_faces = topology.n_faces(), n_ranges = std::max(1, (n_faces + kFacesPerRange - 1) / kFacesPerRange);
  std::vector<PlanTables> parts(static_cast<size_t>(n_ranges));
  std::vector<std::exception_ptr> failures(parts.size());
#pragma omp parallel for schedule(dynamic)
  for (int r = 0; r < n_ranges; ++r) {
    try {
      parts[size_t(r)] = Builder(base, max_depth, bspline_leaves).build(r * kFacesPerRange, std::min(n_faces, (r + 1) * kFacesPerRange));
    } catch (...) {
      failures[size_t(r)] = std::current_exception();
    }
  }
  for (const auto& failure : failures)
    if (failure) std::rethrow_exception(failure);
  PlanTables tables = merge(parts, topology.n_vertices);
  tables.plans.max_depth = max_depth;
  return tables;
}

}  // namespace gps
