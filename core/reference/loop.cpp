#include "core/reference/loop.h"

#include <cmath>
#include <numbers>

#include "core/support/error.h"
#include "core/mesh/element_names.h"
#include "core/mesh/linalg.h"
#include "core/reference/crease_rules.h"
#include "core/reference/vertex_mask.h"

namespace gps {

double loop_beta(int n, LoopBeta kind) {
  if (kind == LoopBeta::warren) return n == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * n);
  const double c = 3.0 / 8.0 + std::cos(2.0 * std::numbers::pi / n) / 4.0;
  return (5.0 / 8.0 - c * c) / n;
}

PolygonTopology loop_topology(const PolygonTopology& t, const MeshConnectivity& c) {
  PolygonTopology out;
  out.n_vertices = t.n_vertices + c.n_edges();
  out.offsets.reserve(4 * size_t(t.n_faces()) + 1);
  out.verts.reserve(12 * size_t(t.n_faces()));
  for (int f = 0; f < t.n_faces(); ++f) {
    if (t.face_size(f) != 3)
      throw ElementError(ElementError::Element::face, f, "Loop subdivision needs a triangle mesh, but ",
                         " has " + std::to_string(t.face_size(f)) + " vertices");
    const int o = t.offsets[size_t(f)];
    const int e[3] = {t.n_vertices + c.face_edges[size_t(o)], t.n_vertices + c.face_edges[size_t(o + 1)],
                      t.n_vertices + c.face_edges[size_t(o + 2)]};
    const int tris[4][3] = {{t.verts[size_t(o)], e[0], e[2]},
                            {t.verts[size_t(o + 1)], e[1], e[0]},
                            {t.verts[size_t(o + 2)], e[2], e[1]},
                            {e[0], e[1], e[2]}};
    for (const auto& tri : tris) {
      out.verts.insert(out.verts.end(), tri, tri + 3);
      out.offsets.push_back(int(out.verts.size()));
    }
  }
  return out;
}

namespace {
// The vertex of triangle f that is not on edge e.
int opposite_vertex(const PolygonTopology& t, const MeshConnectivity& c, int f, int e) {
  const int o = t.offsets[size_t(f)];
  for (int k = 0; k < 3; ++k) {
    const int v = t.verts[size_t(o + k)];
    if (v != c.edge_verts[2 * size_t(e)] && v != c.edge_verts[2 * size_t(e) + 1]) return v;
  }
  return -1;
}
}  // namespace

template <class T>
std::vector<T> loop_values(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<T>& p, LoopBeta kind,
                           const CreaseLevel* creases) {
  const bool creased = creases && !creases->empty();
  const int nv = t.n_vertices, ne = c.n_edges();
  std::vector<T> out(size_t(nv + ne));
  for (int e = 0; e < ne; ++e) {
    const T& a = p[size_t(c.edge_verts[2 * size_t(e)])];
    const T& b = p[size_t(c.edge_verts[2 * size_t(e) + 1])];
    const double sharp = c.is_boundary_edge(e) ? 1.0 : creased ? edge_crease_weight(c, *creases, e) : 0.0;
    if (sharp >= 1.0) {
      out[size_t(nv + e)] = 0.5 * (a + b);
      continue;
    }
    const T& x = p[size_t(opposite_vertex(t, c, c.edge_faces[2 * size_t(e)], e))];
    const T& y = p[size_t(opposite_vertex(t, c, c.edge_faces[2 * size_t(e) + 1], e))];
    out[size_t(nv + e)] = 0.375 * (a + b) + 0.125 * (x + y);
    if (sharp > 0.0) out[size_t(nv + e)] = sharp * (0.5 * (a + b)) + (1.0 - sharp) * out[size_t(nv + e)];
  }
  VertexMask mask;
  const auto point_by_rule = [&](int v, VertexRule rule, int a, int b) {
    if (rule == VertexRule::smooth || rule == VertexRule::dart)
      loop_smooth_vertex_mask(c, v, kind, mask);
    else
      sharp_vertex_mask(rule, v, a, b, BoundaryRule::step, mask);
    return mask.apply(p);
  };
  for (int v = 0; v < nv; ++v) {
    if (creased) {
      const VertexPointRule r = vertex_point_rule(c, *creases, v);
      out[size_t(v)] = point_by_rule(v, r.parent, r.parent_a, r.parent_b);
      if (r.child != r.parent)
        out[size_t(v)] = r.parent_weight * out[size_t(v)] +
                         (1.0 - r.parent_weight) * point_by_rule(v, r.child, r.child_a, r.child_b);
    } else {
      loop_vertex_mask(c, v, kind, mask);
      out[size_t(v)] = mask.apply(p);
    }
  }
  return out;
}

template std::vector<Vec3> loop_values(const PolygonTopology&, const MeshConnectivity&, const std::vector<Vec3>&,
                                       LoopBeta, const CreaseLevel*);
template std::vector<Dual> loop_values(const PolygonTopology&, const MeshConnectivity&, const std::vector<Dual>&,
                                       LoopBeta, const CreaseLevel*);
template std::vector<Eigen::VectorXd> loop_values(const PolygonTopology&, const MeshConnectivity&,
                                                  const std::vector<Eigen::VectorXd>&, LoopBeta, const CreaseLevel*);

}  // namespace gps
