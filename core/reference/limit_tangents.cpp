#include "core/reference/limit_tangents.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

#include "core/mesh/dual_map.h"
#include "core/reference/dart_masks.h"
#include "core/reference/loop.h"
#include "core/reference/vertex_ring.h"

namespace gps {

namespace {

// The tangent masks' weights on the ring of a boundary vertex with k faces: points (v, e_0 … e_k,
// f_0 … f_{k−1}) for quads, (v, e_0 … e_k) for triangles, laid flat as a fan (e_i at angle πi/(k + 1),
// f_i at e_i + e_{i+1}).
using TangentPair = std::vector<Eigen::VectorXd>;

TangentPair boundary_eigenvectors(int k, bool quads) {
  const int n_points = quads ? 2 * k + 2 : k + 2;
  Eigen::MatrixXd flat = Eigen::MatrixXd::Zero(n_points, 2);
  for (int i = 0; i <= k; ++i) flat.row(1 + i) << std::cos(M_PI * i / (k + 1)), std::sin(M_PI * i / (k + 1));
  if (quads)
    for (int i = 0; i < k; ++i) flat.row(k + 2 + i) = flat.row(1 + i) + flat.row(2 + i);
  return tangent_eigenvectors(ring_step_matrix(k, quads, true, LoopBeta::loop), flat);
}

// Once per (number of faces, face size), for every thread.
const TangentPair& cached_boundary_eigenvectors(int k, bool quads) {
  static std::mutex mutex;
  static std::map<std::pair<int, bool>, TangentPair> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find({k, quads});
  if (it == cache.end()) it = cache.emplace(std::make_pair(k, quads), boundary_eigenvectors(k, quads)).first;
  return it->second;
}

bool boundary_masks(int v, const OrderedRing& ring, bool quads, VertexMask& first, VertexMask& second) {
  const TangentPair& pair = cached_boundary_eigenvectors(int(ring.diagonals.size()), quads);
  if (pair.empty()) return false;
  VertexMask* masks[2] = {&first, &second};
  for (int m = 0; m < 2; ++m) {
    const Eigen::VectorXd& w = pair[size_t(m)];
    masks[m]->reset(1.0);
    masks[m]->add_group(w[0], v);
    for (size_t i = 0; i < ring.edges.size(); ++i) masks[m]->add_group(w[long(1 + i)], ring.edges[i]);
    if (quads)
      for (size_t i = 0; i < ring.diagonals.size(); ++i)
        masks[m]->add_group(w[long(1 + ring.edges.size() + i)], ring.diagonals[i]);
  }
  return true;
}

}  // namespace

bool catmull_clark_tangent_masks(const PolygonTopology& t, const MeshConnectivity& c, int v, VertexMask& first,
                                 VertexMask& second) {
  OrderedRing ring;
  if (!ordered_ring(t, c, v, 4, ring)) return false;
  if (ring.boundary) return boundary_masks(v, ring, true, first, second);
  const int n = int(ring.edges.size());
  const double angle = 2.0 * M_PI / n;
  const double a = 1.0 + std::cos(angle) + std::cos(M_PI / n) * std::sqrt(2.0 * (9.0 + std::cos(angle)));
  first.reset(1.0);
  second.reset(1.0);
  for (int i = 0; i < n; ++i) {
    const double c0 = std::cos(angle * i), c1 = std::cos(angle * (i + 1));
    const double s0 = std::sin(angle * i), s1 = std::sin(angle * (i + 1));
    first.add_group(a * c0, ring.edges[size_t(i)]);
    first.add_group(c0 + c1, ring.diagonals[size_t(i)]);
    second.add_group(a * s0, ring.edges[size_t(i)]);
    second.add_group(s0 + s1, ring.diagonals[size_t(i)]);
  }
  return true;
}

bool loop_tangent_masks(const PolygonTopology& t, const MeshConnectivity& c, int v, VertexMask& first,
                        VertexMask& second) {
  OrderedRing ring;
  if (!ordered_ring(t, c, v, 3, ring)) return false;
  if (ring.boundary) return boundary_masks(v, ring, false, first, second);
  const int n = int(ring.edges.size());
  first.reset(1.0);
  second.reset(1.0);
  for (int i = 0; i < n; ++i) {
    first.add_group(std::cos(2.0 * M_PI * i / n), ring.edges[size_t(i)]);
    second.add_group(std::sin(2.0 * M_PI * i / n), ring.edges[size_t(i)]);
  }
  return true;
}

void limit_tangents(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<Dual>& p, bool loop,
                    std::vector<Dual>& first, std::vector<Dual>& second, const CreaseLevel* creases, LoopBeta kind) {
  const auto masks = [&](int v, VertexMask& a, VertexMask& b) {
    if (creases && !creases->empty() && dart_tangent_masks(t, c, *creases, v, !loop, kind, a, b)) return true;
    return loop ? loop_tangent_masks(t, c, v, a, b) : catmull_clark_tangent_masks(t, c, v, a, b);
  };
  first.assign(size_t(t.n_vertices), Dual::Zero());
  second.assign(size_t(t.n_vertices), Dual::Zero());
#pragma omp parallel if (t.n_vertices >= kParallelFaces)
  {
    VertexMask a, b;
#pragma omp for
    for (int v = 0; v < t.n_vertices; ++v)
      if (masks(v, a, b)) {
        first[size_t(v)] = a.apply(p);
        second[size_t(v)] = b.apply(p);
      }
  }
}

Vec3 limit_normal(const Dual& q, const Vec3& mean, const Dual& first, const Dual& second) {
  if (first.isZero(0.0) || second.isZero(0.0)) return Vec3::Zero();
  const Vec3 normal = mean_derivative(q, first, mean).cross(mean_derivative(q, second, mean));
  const double length = normal.norm();
  return length > 1e-300 && std::isfinite(length) ? Vec3(normal / length) : Vec3::Zero();
}

}  // namespace gps
