#include "render/gl/gaussians_change.h"

#include <algorithm>

#include "core/mesh/mesh_connectivity.h"

namespace gps {

bool keeps_vertex_numbers(const std::vector<int>& origin, size_t n_before, size_t n) {
  if (origin.empty()) return n == n_before;
  if (origin.size() != n) return false;
  bool kept = true;  // a loop without an early exit: vectorised
  for (size_t v = 0; v < std::min(n, n_before); ++v) kept &= origin[v] == int(v);
  return kept;
}

GaussiansChange gaussians_change(const FramedGaussians& before, const CovarianceMesh& mesh,
                                 const NormalisedFrame& frame, const std::vector<int>& origin) {
  const size_t n = mesh.n_vertices();
  GaussiansChange change;
  change.n_vertices = n;
  // Compared on all cores (nothing written but a flag per vertex), then listed in order.
  std::vector<char> differs(n);
  const FrameMap map(frame);
#pragma omp parallel for schedule(static) if (n >= size_t(kParallelFaces))
  for (size_t v = 0; v < n; ++v) {
    const size_t o = origin.empty() ? v : size_t(origin[v]);  // −1: past every vertex
    differs[v] = o >= before.n_vertices() || map.mean(mesh.mean(v)) != before.means[o] ||
                 map.covariance(mesh.covariance(v)) != before.covariances[o];
  }
  for (size_t v = 0; v < n; ++v)
    if (differs[v]) change.changed.push_back(int(v));
  const long long n_changed = (long long)change.changed.size();
  change.means.resize(change.changed.size());
  change.covariances.resize(change.changed.size());
#pragma omp parallel for schedule(static) if (n_changed >= kParallelFaces)
  for (long long i = 0; i < n_changed; ++i) {
    const size_t v = size_t(change.changed[size_t(i)]);
    change.means[size_t(i)] = map.mean(mesh.mean(v));
    change.covariances[size_t(i)] = map.covariance(mesh.covariance(v));
  }
  return change;
}

void apply_gaussians_change(const GaussiansChange& change, const std::vector<int>& origin, FramedGaussians& framed) {
  const size_t n_before = framed.n_vertices(), n = change.n_vertices;
  framed.means.resize(n);
  framed.covariances.resize(n);
  // New vertices equal to their origin's Gaussian before (an old vertex's, read before any is written).
  for (size_t v = n_before; v < n; ++v)
    if (const size_t o = origin.empty() ? v : size_t(origin[v]); o < n_before) {
      framed.means[v] = framed.means[o];
      framed.covariances[v] = framed.covariances[o];
    }
  for (size_t i = 0; i < change.changed.size(); ++i) {
    const size_t v = size_t(change.changed[i]);
    framed.means[v] = change.means[i];
    framed.covariances[v] = change.covariances[i];
  }
}

}  // namespace gps
