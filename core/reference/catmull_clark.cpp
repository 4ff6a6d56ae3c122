#include "core/reference/catmull_clark.h"

#include "core/mesh/linalg.h"
#include "core/reference/crease_rules.h"
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
std::vector<T> catmull_clark_values(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<T>& p,
                                    const CreaseLevel* creases) {
  const bool creased = creases && !creases->empty();
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
  for (int e = 0; e < ne; ++e) {  // edge point: (v + w + f1 + f2)/4, or the midpoint on a boundary or crease
    const T& a = p[size_t(c.edge_verts[2 * size_t(e)])];
    const T& b = p[size_t(c.edge_verts[2 * size_t(e) + 1])];
    const double sharp = c.is_boundary_edge(e) ? 1.0 : creased ? edge_crease_weight(c, *creases, e) : 0.0;
    if (sharp >= 1.0) {
      edge_points[e] = 0.5 * (a + b);
      continue;
    }
    edge_points[e] =
        0.25 * (a + b + face_points[c.edge_faces[2 * size_t(e)]] + face_points[c.edge_faces[2 * size_t(e) + 1]]);
    if (sharp > 0.0) edge_points[e] = sharp * (0.5 * (a + b)) + (1.0 - sharp) * edge_points[e];
  }
  // Interior: (n−2)/n·v + Σ e_j/n² + Σ f_j/n², reading the face points.
  const auto smooth_vertex_point = [&](int v) {
    const double n = c.valence(v);
    T sum = T::Zero(p[size_t(v)].rows());
    for (int i = c.vertex_edge_offsets[size_t(v)]; i < c.vertex_edge_offsets[size_t(v) + 1]; ++i)
      sum += p[size_t(c.other_vertex(c.vertex_edges[size_t(i)], v))];
    for (int i = c.vertex_face_offsets[size_t(v)]; i < c.vertex_face_offsets[size_t(v) + 1]; ++i)
      sum += face_points[c.vertex_faces[size_t(i)]];
    return T(((n - 2.0) / n) * p[size_t(v)] + sum / (n * n));
  };
#pragma omp parallel if (parallel)
  {
    VertexMask mask;
    const auto point_by_rule = [&](int v, VertexRule rule, int a, int b) {
      if (rule == VertexRule::smooth || rule == VertexRule::dart) return smooth_vertex_point(v);
      sharp_vertex_mask(rule, v, a, b, BoundaryRule::step, mask);
      return mask.apply(p);
    };
#pragma omp for
    for (int v = 0; v < nv; ++v) {
      if (creased) {
        const VertexPointRule r = vertex_point_rule(c, *creases, v);
        vertex_points[v] = point_by_rule(v, r.parent, r.parent_a, r.parent_b);
        if (r.child != r.parent)
          vertex_points[v] = r.parent_weight * vertex_points[v] +
                             (1.0 - r.parent_weight) * point_by_rule(v, r.child, r.child_a, r.child_b);
      } else if (boundary_mask(c, v, BoundaryRule::step, mask)) {
        vertex_points[v] = mask.apply(p);
      } else {
        vertex_points[v] = smooth_vertex_point(v);
      }
    }
  }
  return out;
}

template std::vector<Vec3> catmull_clark_values(const PolygonTopology&, const MeshConnectivity&,
                                                const std::vector<Vec3>&, const CreaseLevel*);
template std::vector<Eigen::VectorXd> catmull_clark_values(const PolygonTopology&, const MeshConnectivity&,
                                                           const std::vector<Eigen::VectorXd>&, const CreaseLevel*);
template std::vector<Dual> catmull_clark_values(const PolygonTopology&, const MeshConnectivity&,
                                                const std::vector<Dual>&, const CreaseLevel*);

}  // namespace gps
