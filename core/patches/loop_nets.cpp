#include "core/patches/loop_nets.h"

#include <algorithm>
#include <stdexcept>

namespace gps {

int ccw_next(const PolygonTopology& t, const MeshConnectivity& c, int v, int w) {
  for (int i = c.vertex_face_offsets[size_t(v)]; i < c.vertex_face_offsets[size_t(v) + 1]; ++i) {
    const int f = c.vertex_faces[size_t(i)], k = c.vertex_face_corners[size_t(i)], o = t.offsets[size_t(f)];
    if (t.verts[size_t(o + (k + 1) % 3)] == w) return t.verts[size_t(o + (k + 2) % 3)];
  }
  return -1;
}

int cw_next(const PolygonTopology& t, const MeshConnectivity& c, int v, int w) {
  for (int i = c.vertex_face_offsets[size_t(v)]; i < c.vertex_face_offsets[size_t(v) + 1]; ++i) {
    const int f = c.vertex_faces[size_t(i)], k = c.vertex_face_corners[size_t(i)], o = t.offsets[size_t(f)];
    if (t.verts[size_t(o + (k + 2) % 3)] == w) return t.verts[size_t(o + (k + 1) % 3)];
  }
  return -1;
}

namespace {

// Appends v's fan (triangle_fan) to `fan`.
void append_fan(const PolygonTopology& t, const MeshConnectivity& c, int v, std::vector<int>& fan) {
  const int valence = c.valence(v);
  if (valence == 0) return;
  int start = c.other_vertex(c.vertex_edges[size_t(c.vertex_edge_offsets[size_t(v)])], v);
  if (vertex_role(c, v) != VertexRole::interior)  // walk clockwise to the boundary start
    for (int x = cw_next(t, c, v, start), guard = 0; x >= 0 && guard < valence; x = cw_next(t, c, v, start), ++guard)
      start = x;
  fan.push_back(start);
  for (int x = ccw_next(t, c, v, start), n = 1; x >= 0 && x != start && n < valence; x = ccw_next(t, c, v, x), ++n)
    fan.push_back(x);
}

}  // namespace

std::vector<int> triangle_fan(const PolygonTopology& t, const MeshConnectivity& c, int v) {
  std::vector<int> fan;
  fan.reserve(size_t(c.valence(v)));
  append_fan(t, c, v, fan);
  return fan;
}

bool loop_regular_vertex(const MeshConnectivity& c, int v) {
  switch (vertex_role(c, v)) {
    case VertexRole::interior:
      return c.n_vertex_faces(v) == 6;
    case VertexRole::boundary:
      return c.n_vertex_faces(v) == 3;
    default:
      return false;
  }
}

TriangleWalker::TriangleWalker(const PolygonTopology& topology, const MeshConnectivity& connectivity)
    : t_(topology), c_(connectivity) {
  fan_offsets_.reserve(size_t(t_.n_vertices) + 1);
  fans_.reserve(c_.vertex_edges.size());
  fan_offsets_.push_back(0);
  for (int v = 0; v < t_.n_vertices; ++v) {
    append_fan(t_, c_, v, fans_);
    fan_offsets_.push_back(int(fans_.size()));
  }
}

std::vector<int> TriangleWalker::ring_from(int v, int first) const {
  const int* f = fan(v);
  const int n = fan_size(v);
  const int at = int(std::find(f, f + n, first) - f);
  std::vector<int> ring;
  ring.reserve(size_t(n));
  if (vertex_role(c_, v) == VertexRole::interior) {
    for (int i = 0; i < n; ++i) ring.push_back(f[(at + i) % n]);
  } else {  // counter-clockwise to the boundary end, then clockwise from `first` to the start
    for (int i = at; i < n; ++i) ring.push_back(f[i]);
    for (int i = at - 1; i >= 0; --i) ring.push_back(f[i]);
  }
  return ring;
}

namespace {

// Lattice directions counter-clockwise: (1,0) (0,1) (−1,1) (−1,0) (0,−1) (1,−1).
constexpr int kDirection[6][2] = {{1, 0}, {0, 1}, {-1, 1}, {-1, 0}, {0, -1}, {1, -1}};
// Lattice positions of the 12 net points (core/patches/patch_basis.h order).
constexpr int kNet[12][2] = {{0, 0},  {1, 0},  {0, 1}, {-1, 0}, {0, -1}, {1, -1},
                             {-1, 1}, {2, -1}, {2, 0}, {1, 1},  {0, 2},  {-1, 2}};

int net_index(int i, int j) {
  for (int k = 0; k < 12; ++k)
    if (kNet[k][0] == i && kNet[k][1] == j) return k;
  return -1;
}

// The six lattice neighbours of a regular vertex c with the counter-clockwise fan `fan` (a boundary
// vertex's from its boundary start), `first` lying in direction d0; a boundary vertex's two missing
// ones are phantoms, reflections across its boundary edges.
std::array<VertexCombination, 6> lattice_ring(const std::vector<int>& fan, int c, int first, int d0) {
  std::array<VertexCombination, 6> ring;
  const int shift = int(std::find(fan.begin(), fan.end(), first) - fan.begin());
  for (size_t j = 0; j < fan.size(); ++j) ring[size_t((d0 + int(j) - shift + 12) % 6)] = {{fan[j], 1.0}};
  if (fan.size() == 4) {  // regular boundary: d(f3)+1 = f3 − f2 + c, d(f0)−1 = f0 − f1 + c
    const int d3 = (d0 + 3 - shift + 12) % 6, d0f = (d0 - shift + 12) % 6;
    ring[size_t((d3 + 1) % 6)] = {{fan[3], 1.0}, {fan[2], -1.0}, {c, 1.0}};
    ring[size_t((d0f + 5) % 6)] = {{fan[0], 1.0}, {fan[1], -1.0}, {c, 1.0}};
  } else if (fan.size() != 6) {
    throw std::logic_error("loop_regular_net: vertex " + std::to_string(c) + " is not regular");
  }
  return ring;
}

}  // namespace

std::array<VertexCombination, 12> loop_regular_net(const TriangleWalker& w, int v0, int v1, int v2) {
  const auto fan = [&](int v) { return std::vector<int>(w.fan(v), w.fan(v) + w.fan_size(v)); };
  return loop_regular_net(v0, v1, v2, {fan(v0), fan(v1), fan(v2)});
}

std::array<VertexCombination, 12> loop_regular_net(int v0, int v1, int v2, const std::array<std::vector<int>, 3>& fans) {
  std::array<VertexCombination, 12> net;
  net[0] = {{v0, 1.0}};
  net[1] = {{v1, 1.0}};
  net[2] = {{v2, 1.0}};
  // Each corner: its lattice position and the direction of the next corner from it.
  const int corner[3] = {v0, v1, v2}, next[3] = {v1, v2, v0}, at[3][2] = {{0, 0}, {1, 0}, {0, 1}}, d0[3] = {0, 2, 4};
  for (int k = 0; k < 3; ++k) {
    const auto ring = lattice_ring(fans[size_t(k)], corner[k], next[k], d0[k]);
    for (int d = 0; d < 6; ++d) {
      const int n = net_index(at[k][0] + kDirection[d][0], at[k][1] + kDirection[d][1]);
      if (n < 0) continue;
      // A real vertex wins over a phantom of the same point seen from another corner.
      if (net[size_t(n)].empty() || (net[size_t(n)].size() > 1 && ring[size_t(d)].size() == 1))
        net[size_t(n)] = ring[size_t(d)];
    }
  }
  return net;
}

std::vector<int> loop_extraordinary_neighbourhood(const TriangleWalker& w, int v, int a, int b) {
  std::vector<int> points = {v};
  const std::vector<int> ring = w.ring_from(v, a);
  points.insert(points.end(), ring.begin(), ring.end());
  for (const int corner : {a, b})
    for (const int x : w.ring_from(corner, v))
      if (std::find(points.begin(), points.end(), x) == points.end()) points.push_back(x);
  return points;
}

}  // namespace gps
