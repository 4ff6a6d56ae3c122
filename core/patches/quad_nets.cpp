#include "core/patches/quad_nets.h"

#include <stdexcept>

#include "core/reference/vertex_mask.h"

namespace gps {

namespace {

using Combo = LocalCombination;

struct Grid2 {
  int i, j;
  Grid2 operator+(Grid2 o) const { return {i + o.i, j + o.j}; }
  Grid2 operator-(Grid2 o) const { return {i - o.i, j - o.j}; }
};

// Corner k of a node's quad sits at grid position kCorner[k] of its 4×4 B-spline net; kOut[k] points
// away from the quad across edge k (from corner k to corner k+1).
constexpr Grid2 kCorner[4] = {{1, 1}, {2, 1}, {2, 2}, {1, 2}};
constexpr Grid2 kOut[4] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};

}  // namespace

int face_vertex(const LocalMesh& m, int f, int k) {
  const int n = m.topology().face_size(f);
  // Callers step a few corners from a corner index: a subtraction, not two divisions, which would
  // cost a large share of bspline_net's time.
  if (k >= n) k -= n;
  if (k < 0) k += n;
  if (k < 0 || k >= n) k = ((k % n) + n) % n;
  return m.topology().verts[size_t(m.topology().offsets[size_t(f)] + k)];
}

int corner_index(const LocalMesh& m, int f, int v) {
  const int* verts = m.topology().verts.data() + m.topology().offsets[size_t(f)];
  for (int k = 0, n = m.topology().face_size(f); k < n; ++k)
    if (verts[k] == v) return k;
  throw std::logic_error("plan builder: vertex not in face");
}

int other_face(const LocalMesh& m, int e, int f) {
  const int a = m.connectivity().edge_faces[2 * size_t(e)], b = m.connectivity().edge_faces[2 * size_t(e) + 1];
  return a == f ? b : a;
}

bool regular_vertex(const LocalMesh& m, int v) {
  const auto& c = m.connectivity();
  if (!m.complete[size_t(v)]) return false;
  for (int i = c.vertex_face_offsets[size_t(v)]; i < c.vertex_face_offsets[size_t(v) + 1]; ++i)
    if (m.topology().face_size(c.vertex_faces[size_t(i)]) != 4) return false;
  switch (vertex_role(c, v)) {
    case VertexRole::interior:
      return c.n_vertex_faces(v) == 4;
    case VertexRole::boundary:
      return c.n_vertex_faces(v) == 2;
    case VertexRole::corner:
      return true;
    case VertexRole::isolated:
      return false;
  }
  return false;
}

namespace {

// The faces of q's sector at v (see regular_corner), or −1 where one of them is not a quad.
int quad_sector_size(const LocalMesh& m, int v, int q) {
  if (m.topology().face_size(q) != 4) return -1;
  int count = 1;
  for (const int step : {1, -1}) {
    int f = q;
    for (;;) {
      const int e = m.find_edge(v, face_vertex(m, f, corner_index(m, f, v) + step));
      if (m.is_cut_edge(e)) break;
      f = other_face(m, e, f);
      if (f == q) return count;  // all the way round: no cut edge at v
      if (m.topology().face_size(f) != 4) return -1;
      ++count;
    }
  }
  return count;
}

}  // namespace

bool regular_corner(const LocalMesh& m, int v, int q) {
  if (!m.has_creases()) return regular_vertex(m, v);
  if (!m.complete[size_t(v)]) return false;
  const auto [semi_sharp, cut, sharp_corner] = m.sharpness_at(v);
  if (semi_sharp) return false;
  const int sector = quad_sector_size(m, v, q);
  if (cut == 0 && !sharp_corner) return sector == 4;
  // Sdc's rules: a sharp vertex, more than two sharp edges, or a boundary vertex with one face is a corner.
  const bool corner_rule = sharp_corner || cut > 2 || m.connectivity().n_vertex_faces(v) == 1;
  if (corner_rule) return sector == 1;
  return cut == 2 && sector == 2;
}

void bspline_net(const LocalMesh& m, int q, const std::array<int, 4>& c, std::array<LocalCombination, 16>& net) {
  const auto at = [&](Grid2 g) -> Combo& { return net[size_t(g.i + 4 * g.j)]; };
  const auto set_vertex = [&](Grid2 g, int v) {
    Combo& p = at(g);
    p.clear();
    p.emplace_back(v, 1.0);
  };
  // p₋₁ = 2p₀ − p₁ (g + out = 2·g − (g − out)).
  const auto mirror = [&](Grid2 g, Grid2 out) {
    Combo& p = at(g + out);
    p.clear();
    for (const auto& [v, x] : at(g)) p.emplace_back(v, 2.0 * x);
    for (const auto& [v, x] : at(g - out)) p.emplace_back(v, -x);
  };
  bool boundary_edge[4];
  for (int k = 0; k < 4; ++k) set_vertex(kCorner[k], c[size_t(k)]);
  for (int k = 0; k < 4; ++k) {
    const int a = c[size_t(k)], b = c[size_t((k + 1) % 4)];
    const int e = m.find_edge(a, b);
    boundary_edge[k] = m.is_cut_edge(e);
    if (boundary_edge[k]) {
      mirror(kCorner[k], kOut[k]);
      mirror(kCorner[(k + 1) % 4], kOut[k]);
      continue;
    }
    const int n = other_face(m, e, q), j = corner_index(m, n, a);  // n runs b, a, x, y
    set_vertex(kCorner[k] + kOut[k], face_vertex(m, n, j + 1));
    set_vertex(kCorner[(k + 1) % 4] + kOut[k], face_vertex(m, n, j + 2));
  }
  for (int k = 0; k < 4; ++k) {
    const Grid2 g = kCorner[k], o1 = kOut[k], o2 = kOut[(k + 3) % 4];
    const int v = c[size_t(k)];
    if (!boundary_edge[k] && !boundary_edge[(k + 3) % 4]) {  // a smooth corner: the face diagonally across
      const auto& conn = m.connectivity();
      for (int i = conn.vertex_face_offsets[size_t(v)]; i < conn.vertex_face_offsets[size_t(v) + 1]; ++i) {
        const int f = conn.vertex_faces[size_t(i)], kv = conn.vertex_face_corners[size_t(i)];
        const int prev = face_vertex(m, f, kv + 3), next = face_vertex(m, f, kv + 1);
        if (f == q || prev == c[size_t((k + 1) % 4)] || next == c[size_t((k + 1) % 4)] ||
            prev == c[size_t((k + 3) % 4)] || next == c[size_t((k + 3) % 4)])
          continue;
        set_vertex(g + o1 + o2, face_vertex(m, f, kv + 2));
      }
    } else if (boundary_edge[(k + 3) % 4]) {
      mirror(g + o1, o2);
    } else {
      mirror(g + o2, o1);
    }
  }
}

std::array<LocalCombination, 16> bezier_net(const LocalMesh& m, const std::array<int, 4>& c) {
  static constexpr Grid2 kBezier[4] = {{0, 0}, {3, 0}, {3, 3}, {0, 3}};
  const auto& conn = m.connectivity();
  std::array<Combo, 16> net;
  const auto at = [&](Grid2 g) -> Combo& { return net[size_t(g.i + 4 * g.j)]; };
  VertexMask corner_mask;
  for (int k = 0; k < 4; ++k) {
    const int v = c[size_t(k)], next = c[size_t((k + 1) % 4)], prev = c[size_t((k + 3) % 4)],
              opposite = c[size_t((k + 2) % 4)];
    const VertexRole role = vertex_role(conn, v);
    const int n = conn.valence(v);
    const double nr = role == VertexRole::interior ? n : 4.0;  // boundary vertices take regular weights
    const Grid2 g = kBezier[k];
    const Grid2 to_next = {(kBezier[(k + 1) % 4].i - g.i) / 3, (kBezier[(k + 1) % 4].j - g.j) / 3};
    const Grid2 to_prev = {(kBezier[(k + 3) % 4].i - g.i) / 3, (kBezier[(k + 3) % 4].j - g.j) / 3};
    // Corner point: the exact limit position.
    catmull_clark_limit_mask(m.topology(), conn, v, corner_mask);
    at(g) = corner_mask.terms();
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

}  // namespace gps
