#include "core/reference/refined_outer_edges.h"

namespace gps {

std::vector<int> outer_half_edges(const MeshConnectivity& c, int n_vertices, bool parallel) {
  std::vector<int> outer(2 * size_t(c.n_edges()));
#pragma omp parallel for if (parallel)
  for (int v = 0; v < n_vertices; ++v)
    for (int i = c.vertex_edge_offsets[size_t(v)]; i < c.vertex_edge_offsets[size_t(v) + 1]; ++i) {
      const int e = c.vertex_edges[size_t(i)];
      outer[2 * size_t(e) + (c.edge_verts[2 * size_t(e)] == v ? 0 : 1)] = i;
    }
  return outer;
}

void write_outer_half_edges(const MeshConnectivity& c, int v, int n_vertices, MeshConnectivity& r) {
  r.vertex_edge_offsets[size_t(v)] = c.vertex_edge_offsets[size_t(v)];
  for (int i = c.vertex_edge_offsets[size_t(v)]; i < c.vertex_edge_offsets[size_t(v) + 1]; ++i) {
    r.edge_verts[2 * size_t(i)] = v;
    r.edge_verts[2 * size_t(i) + 1] = n_vertices + c.vertex_edges[size_t(i)];
    r.vertex_edges[size_t(i)] = i;
  }
}

}  // namespace gps
