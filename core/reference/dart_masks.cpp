#include "core/reference/dart_masks.h"

#include <Eigen/QR>

#include <algorithm>
#include <map>
#include <mutex>
#include <tuple>

#include "core/reference/crease_rules.h"
#include "core/reference/vertex_ring.h"

namespace gps {

namespace {

// The weights (v, e_0 … e_{k−1}, f_0 … f_{k−1}) of the limit of a dart with k faces whose sharp
// edge is (v, e_0): l with l·S = l and Σl = 1 for the ring's step S.
Eigen::VectorXd dart_weights(int k, bool quads, LoopBeta kind) {
  const Eigen::MatrixXd step = ring_step_matrix(k, quads, false, kind, 0);
  const long n = step.rows();
  Eigen::MatrixXd system(n + 1, n);
  system.topRows(n) = step.transpose() - Eigen::MatrixXd::Identity(n, n);
  system.row(n).setOnes();
  Eigen::VectorXd right = Eigen::VectorXd::Zero(n + 1);
  right[n] = 1.0;
  return system.colPivHouseholderQr().solve(right);
}

// Once per (faces, face size, β), for every thread.
const Eigen::VectorXd& cached_dart_weights(int k, bool quads, LoopBeta kind) {
  static std::mutex mutex;
  static std::map<std::tuple<int, bool, LoopBeta>, Eigen::VectorXd> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  const auto key = std::make_tuple(k, quads, quads ? LoopBeta::loop : kind);
  auto it = cache.find(key);
  if (it == cache.end()) it = cache.emplace(key, dart_weights(k, quads, kind)).first;
  return it->second;
}

// The far end of v's one sharp edge when that edge is infinitely sharp; -1 otherwise.
int infinitely_sharp_neighbour(const MeshConnectivity& c, const CreaseLevel& level, int v) {
  for (int i = c.vertex_edge_offsets[size_t(v)]; i < c.vertex_edge_offsets[size_t(v) + 1]; ++i) {
    const int e = c.vertex_edges[size_t(i)];
    if (is_infinitely_sharp(edge_sharpness(c, level, e))) return c.other_vertex(e, v);
  }
  return -1;
}

}  // namespace

bool dart_limit_mask(const PolygonTopology& t, const MeshConnectivity& c, const CreaseLevel& level, int v, bool quads,
                     LoopBeta kind, VertexMask& mask) {
  if (vertex_rule(c, level, v) != VertexRule::dart) return false;
  const int sharp = infinitely_sharp_neighbour(c, level, v);
  OrderedRing ring;
  if (sharp < 0 || !ordered_ring(t, c, v, quads ? 4 : 3, ring) || ring.boundary) return false;
  const int k = int(ring.edges.size());
  const auto at = std::find(ring.edges.begin(), ring.edges.end(), sharp);
  if (at == ring.edges.end()) return false;
  const int first = int(at - ring.edges.begin());
  const Eigen::VectorXd& w = cached_dart_weights(k, quads, kind);
  mask.reset(1.0);
  mask.add_group(w[0], v);
  for (int i = 0; i < k; ++i) mask.add_group(w[1 + i], ring.edges[size_t((first + i) % k)]);
  if (quads)
    for (int i = 0; i < k; ++i) mask.add_group(w[1 + k + i], ring.diagonals[size_t((first + i) % k)]);
  return true;
}

}  // namespace gps
