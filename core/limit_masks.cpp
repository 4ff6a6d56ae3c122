#include "core/limit_masks.h"

#include "core/linalg.h"

namespace gps {

bool all_quads(const PolygonTopology& t) {
  for (int f = 0; f < t.n_faces(); ++f)
    if (t.face_size(f) != 4) return false;
  return true;
}

namespace {
// Boundary and corner limits, shared by both schemes; returns false for interior vertices.
template <class T>
bool boundary_limit(const MeshConnectivity& c, const std::vector<T>& p, int v, T& out) {
  int a = -1, b = -1;
  switch (vertex_role(c, v, &a, &b)) {
    case VertexRole::isolated:
    case VertexRole::corner:
      out = p[size_t(v)];
      return true;
    case VertexRole::boundary:
      out = (p[size_t(a)] + 4.0 * p[size_t(v)] + p[size_t(b)]) / 6.0;
      return true;
    case VertexRole::interior:
      return false;
  }
  return false;
}
}  // namespace

template <class T>
std::vector<T> catmull_clark_limit(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<T>& p) {
  std::vector<T> out(p.size());
#pragma omp parallel for if (t.n_vertices >= kParallelFaces)
  for (int v = 0; v < t.n_vertices; ++v) {
    if (boundary_limit(c, p, v, out[size_t(v)])) continue;
    const double n = c.valence(v);
    T edges = T::Zero(p[size_t(v)].rows()), diagonals = T::Zero(p[size_t(v)].rows());
    for (int i = c.vertex_edge_offsets[size_t(v)]; i < c.vertex_edge_offsets[size_t(v) + 1]; ++i)
      edges += p[size_t(c.other_vertex(c.vertex_edges[size_t(i)], v))];
    for (int i = c.vertex_face_offsets[size_t(v)]; i < c.vertex_face_offsets[size_t(v) + 1]; ++i) {
      const int f = c.vertex_faces[size_t(i)], k = c.vertex_face_corners[size_t(i)];
      diagonals += p[size_t(t.verts[size_t(t.offsets[size_t(f)] + (k + 2) % 4)])];
    }
    out[size_t(v)] = (n * n * p[size_t(v)] + 4.0 * edges + diagonals) / (n * (n + 5.0));
  }
  return out;
}

template <class T>
std::vector<T> loop_limit(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<T>& p, LoopBeta kind) {
  std::vector<T> out(p.size());
#pragma omp parallel for if (t.n_vertices >= kParallelFaces)
  for (int v = 0; v < t.n_vertices; ++v) {
    if (boundary_limit(c, p, v, out[size_t(v)])) continue;
    const int n = c.valence(v);
    const double chi = 1.0 / (3.0 / (8.0 * loop_beta(n, kind)) + n);
    T sum = T::Zero(p[size_t(v)].rows());
    for (int i = c.vertex_edge_offsets[size_t(v)]; i < c.vertex_edge_offsets[size_t(v) + 1]; ++i)
      sum += p[size_t(c.other_vertex(c.vertex_edges[size_t(i)], v))];
    out[size_t(v)] = (1.0 - n * chi) * p[size_t(v)] + chi * sum;
  }
  return out;
}

template std::vector<Vec3> catmull_clark_limit(const PolygonTopology&, const MeshConnectivity&, const std::vector<Vec3>&);
template std::vector<Dual> catmull_clark_limit(const PolygonTopology&, const MeshConnectivity&, const std::vector<Dual>&);
template std::vector<Vec3> loop_limit(const PolygonTopology&, const MeshConnectivity&, const std::vector<Vec3>&, LoopBeta);
template std::vector<Dual> loop_limit(const PolygonTopology&, const MeshConnectivity&, const std::vector<Dual>&, LoopBeta);
template std::vector<Eigen::VectorXd> loop_limit(const PolygonTopology&, const MeshConnectivity&, const std::vector<Eigen::VectorXd>&, LoopBeta);

}  // namespace gps
