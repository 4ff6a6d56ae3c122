#include "render/reference_triangles.h"

#include <Eigen/Geometry>

#include "core/reference_subdivision.h"

namespace gps {

TriangleMesh reference_triangles(const CovarianceMesh& mesh, int levels, const PlanOptions& options) {
  const SubdivisionResult r = subdivide(mesh, {scheme_for(topology_of(mesh.mesh), options), levels, true, options.loop_beta});
  TriangleMesh t;
  t.positions.resize(r.mesh.n_vertices());
  t.normals.assign(r.mesh.n_vertices(), Vec3::Zero());
  for (size_t i = 0; i < t.positions.size(); ++i) t.positions[i] = r.mesh.mean(i);
  for (const auto f : r.mesh.mesh.faces()) {
    std::vector<int> v;
    for (const auto h : r.mesh.mesh.fv_range(f)) v.push_back(h.idx());
    for (size_t k = 1; k + 1 < v.size(); ++k) {
      t.triangles.push_back({v[0], v[k], v[k + 1]});
      const Vec3 n = (t.positions[size_t(v[k])] - t.positions[size_t(v[0])]).cross(t.positions[size_t(v[k + 1])] - t.positions[size_t(v[0])]);
      for (const int i : {v[0], v[k], v[k + 1]}) t.normals[size_t(i)] += n;
    }
  }
  for (Vec3& n : t.normals) n.normalize();
  return t;
}

}  // namespace gps
