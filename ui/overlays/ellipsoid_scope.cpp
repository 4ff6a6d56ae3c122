#include "ui/overlays/ellipsoid_scope.h"

#include <algorithm>

namespace gps {

bool all_ellipsoids(EllipsoidScope scope, size_t n_vertices) {
  switch (scope) {
    case EllipsoidScope::all:
      return true;
    case EllipsoidScope::neighbourhood:
      return false;
    case EllipsoidScope::automatic:
      return n_vertices <= kAllEllipsoidsUpTo;
  }
  return true;
}

std::vector<int> selection_neighbourhood(const CovarianceMesh& mesh, const std::vector<int>& selected) {
  std::vector<int> out;
  for (const int v : selected) {
    if (v < 0 || size_t(v) >= mesh.n_vertices()) continue;
    out.push_back(v);
    const MeshConnectivity& c = mesh.connectivity();
    for (int k = c.vertex_edge_offsets[size_t(v)]; k < c.vertex_edge_offsets[size_t(v) + 1]; ++k)
      out.push_back(c.other_vertex(c.vertex_edges[size_t(k)], v));
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace gps
