#include "core/reference/dart_masks.h"

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
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

// The ring of a dart k faces round laid flat: e_i at angle 2πi/k, f_i at e_i + e_{i+1}.
Eigen::MatrixXd flat_dart_ring(int k, bool quads) {
  Eigen::MatrixXd flat = Eigen::MatrixXd::Zero(quads ? 2 * k + 1 : k + 1, 2);
  for (int i = 0; i < k; ++i) flat.row(1 + i) << std::cos(2 * M_PI * i / k), std::sin(2 * M_PI * i / k);
  if (quads)
    for (int i = 0; i < k; ++i) flat.row(1 + k + i) = flat.row(1 + i) + flat.row(1 + (i + 1) % k);
  return flat;
}

// The weights of a dart's masks on its ring: its limit, then its two tangents (none where its step
// has no tangent pair); once per (faces, face size, β), for every thread.
const std::vector<Eigen::VectorXd>& cached_dart_weights(int k, bool quads, LoopBeta kind) {
  static std::mutex mutex;
  static std::map<std::tuple<int, bool, LoopBeta>, std::vector<Eigen::VectorXd>> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  const auto key = std::make_tuple(k, quads, quads ? LoopBeta::loop : kind);
  auto it = cache.find(key);
  if (it == cache.end()) {
    std::vector<Eigen::VectorXd> weights = {dart_weights(k, quads, kind)};
    for (Eigen::VectorXd& tangent :
         tangent_eigenvectors(ring_step_matrix(k, quads, false, kind, 0), flat_dart_ring(k, quads)))
      weights.push_back(std::move(tangent));
    it = cache.emplace(key, std::move(weights)).first;
  }
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

// v's ring turned to start at its sharp edge when v is a dart of an infinitely sharp edge whose faces
// all have `face_size` corners; false otherwise.
bool dart_ring(const PolygonTopology& t, const MeshConnectivity& c, const CreaseLevel& level, int v, int face_size,
               OrderedRing& ring) {
  if (vertex_rule(c, level, v) != VertexRule::dart) return false;
  const int sharp = infinitely_sharp_neighbour(c, level, v);
  if (sharp < 0 || !ordered_ring(t, c, v, face_size, ring) || ring.boundary) return false;
  const auto at = std::find(ring.edges.begin(), ring.edges.end(), sharp);
  if (at == ring.edges.end()) return false;
  const long first = at - ring.edges.begin();
  std::rotate(ring.edges.begin(), ring.edges.begin() + first, ring.edges.end());
  std::rotate(ring.diagonals.begin(), ring.diagonals.begin() + first, ring.diagonals.end());
  return true;
}

// `weights` (v, e_0 … e_{k−1}, f_0 … f_{k−1}) as a mask on the ring.
void put_mask(int v, const OrderedRing& ring, bool quads, const Eigen::VectorXd& weights, VertexMask& mask) {
  const size_t k = ring.edges.size();
  mask.reset(1.0);
  mask.add_group(weights[0], v);
  for (size_t i = 0; i < k; ++i) mask.add_group(weights[long(1 + i)], ring.edges[i]);
  if (quads)
    for (size_t i = 0; i < k; ++i) mask.add_group(weights[long(1 + k + i)], ring.diagonals[i]);
}

}  // namespace

bool dart_limit_mask(const PolygonTopology& t, const MeshConnectivity& c, const CreaseLevel& level, int v, bool quads,
                     LoopBeta kind, VertexMask& mask) {
  OrderedRing ring;
  if (!dart_ring(t, c, level, v, quads ? 4 : 3, ring)) return false;
  put_mask(v, ring, quads, cached_dart_weights(int(ring.edges.size()), quads, kind)[0], mask);
  return true;
}

bool dart_tangent_masks(const PolygonTopology& t, const MeshConnectivity& c, const CreaseLevel& level, int v,
                        bool quads, LoopBeta kind, VertexMask& first, VertexMask& second) {
  OrderedRing ring;
  if (!dart_ring(t, c, level, v, quads ? 4 : 3, ring)) return false;
  const std::vector<Eigen::VectorXd>& weights = cached_dart_weights(int(ring.edges.size()), quads, kind);
  if (weights.size() < 3) return false;
  put_mask(v, ring, quads, weights[1], first);
  put_mask(v, ring, quads, weights[2], second);
  return true;
}

}  // namespace gps
