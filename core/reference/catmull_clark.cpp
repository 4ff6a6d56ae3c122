#include "core/reference/catmull_clark.h"

#include "core/mesh/linalg.h"
#include "core/reference/vertex_mask.h"

namespace gps {

PolygonTopology catmull_clark_topology(const PolygonTopology& t, const MeshConnectivity& c) {
  PolygonTopology out;
  const int edge_base = t.n_vertices, face_base = t.n_vertices + c.n_edges();
  out.n_vertices = face_base + t.n_faces();
  out.offsets.reserve(t.verts.size() + 1);
  out.verts.reserve(4 * t.verts.size());
  for (int f = 0; f < t.n_faces(); ++f) {
    const int begin = t.offsets[size_t(f)], n = t.face_size(f);
    for (int k = 0; k < n; ++k) {
      out.verts.push_back(t.verts[size_t(begin + k)]);
      out.verts.push_back(edge_base + c.face_edges[size_t(begin + k)]);
      out.verts.push_back(face_base + f);
      out.verts.push_back(edge_base + c.face_edges[size_t(begin + (k + n - 1) % n)]);
      out.offsets.push_back(int(out.verts.size()));
    }
  }
  return out;
}

template <class T>
std::vector<T> catmull_clark_values(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<T>& p) {
  const int nv = t.n_vertices, ne = c.n_edges(), nf = t.n_faces();
  std::vector<T> out(size_t(nv + ne + nf));
  T* vertex_points = out.data();
  T* edge_points = out.data() + nv;
  T* face_points = out.data() + nv + ne;
  // Each point reads only the input and the face points: the loops run on all cores (OpenMP) on a
  // large mesh, with results identical to a serial run.
  const bool parallel = nf >= kParallelFaces;
#pragma omp parallel for if (parallel)
  for (int f = 0; f < nf; ++f) {  // face point: the centroid
    T sum = p[size_t(t.verts[size_t(t.offsets[size_t(f)])])];
    for (int i = t.offsets[size_t(f)] + 1; i < t.offsets[size_t(f) + 1]; ++i) sum += p[size_t(t.verts[size_t(i)])];
    face_points[f] = sum / double(t.face_size(f));
  }
#pragma omp parallel for if (parallel)
  for (int e = 0; e < ne; ++e) {  // edge point: (v + w + f1 + f2)/4, or the midpoint on a boundary
    const T& a = p[size_t(c.edge_verts[2 * size_t(e)])];
    const T& b = p[size_t(c.edge_verts[2 * size_t(e) + 1])];
    if (c.is_boundary_edge(e))
      edge_points[e] = 0.5 * (a + b);
    else
      edge_points[e] =
          0.25 * (a + b + face_points[c.edge_faces[2 * size_t(e)]] + face_points[c.edge_faces[2 * size_t(e) + 1]]);
  }
#pragma omp parallel if (parallel)
  {
    VertexMask boundary;
#pragma omp for
    for (int v = 0; v < nv; ++v) {
      if (boundary_mask(c, v, BoundaryRule::step, boundary)) {
        vertex_points[v] = boundary.apply(p);
        continue;
      }
      // Interior: (n−2)/n·v + Σ e_j/n² + Σ f_j/n², reading the face points.
      const double n = c.valence(v);
      T sum = T::Zero(p[size_t(v)].rows());
      for (int i = c.vertex_edge_offsets[size_t(v)]; i < c.vertex_edge_offsets[size_t(v) + 1]; ++i)
        sum += p[size_t(c.other_vertex(c.vertex_edges[size_t(i)], v))];
      for (int i = c.vertex_face_offsets[size_t(v)]; i < c.vertex_face_offsets[size_t(v) + 1]; ++i)
        sum += face_points[c.vertex_faces[size_t(i)]];
      vertex_points[v] = ((n - 2.0) / n) * p[size_t(v)] + sum / (n * n);
    }
  }
  return out;
}

template std::vector<Vec3> catmull_clark_values(const PolygonTopology&, const MeshConnectivity&,
                                                const std::vector<Vec3>&);
template std::vector<Eigen::VectorXd> catmull_clark_values(const PolygonTopology&, const MeshConnectivity&,
                                                           const std::vector<Eigen::VectorXd>&);
template std::vector<Dual> catmull_clark_values(const PolygonTopology&, const MeshConnectivity&,
                                                const std::vector<Dual>&);

}  // namespace gps
