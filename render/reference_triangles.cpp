#include "render/reference_triangles.h"

#include <Eigen/Geometry>

#include "core/reference_subdivision.h"

namespace gps {

namespace {
// Which diagonal splits a quad of the reference: the one through the corner nearest its patch's
// centre, as the tessellator's diagonals run in each quadrant of a patch (Mesa's, after Direct3D's
// reference tessellator: mirrored about the centre). Equal diagonals make equal triangles, so the
// thesis' difference images between the patches and the reference show the surfaces, not the
// triangulations.
int corner_nearest_centre(const PatchParam* corners) {
  int best = 0;
  double nearest = 1e300;
  for (int k = 0; k < 4; ++k) {
    const double du = corners[k].u - 0.5, dv = corners[k].v - 0.5, d = du * du + dv * dv;
    if (d < nearest - 1e-12) nearest = d, best = k;
  }
  return best;
}
}  // namespace

TriangleMesh reference_triangles(const CovarianceMesh& mesh, int levels, const PlanOptions& options) {
  const SubdivisionResult r = subdivide(mesh, {scheme_for(topology_of(mesh.mesh), options), levels, true, options.loop_beta, true});
  const PolygonTopology t = topology_of(r.mesh.mesh);
  TriangleMesh out;
  out.positions.resize(r.mesh.n_vertices());
  for (size_t i = 0; i < out.positions.size(); ++i) out.positions[i] = r.mesh.mean(i);
  std::vector<Vec3> around(out.positions.size(), Vec3::Zero());  // area-weighted face normals
  const bool quad_cells = r.corner_params.size() == t.verts.size();
  for (int f = 0; f < t.n_faces(); ++f) {
    const int o = t.offsets[size_t(f)], n = t.face_size(f);
    const int first = n == 4 && quad_cells ? corner_nearest_centre(&r.corner_params[size_t(o)]) : 0;
    const auto corner = [&](int k) { return t.verts[size_t(o + (first + k) % n)]; };
    for (int k = 1; k + 1 < n; ++k) {
      out.triangles.push_back({corner(0), corner(k), corner(k + 1)});
      const Vec3& a = out.positions[size_t(corner(0))];
      const Vec3 normal = (out.positions[size_t(corner(k))] - a).cross(out.positions[size_t(corner(k + 1))] - a);
      for (const int i : {corner(0), corner(k), corner(k + 1)}) around[size_t(i)] += normal;
    }
  }
  out.normals.resize(out.positions.size());
  for (size_t i = 0; i < out.normals.size(); ++i)
    out.normals[i] = r.normals[i].isZero(0.0) ? around[i].normalized() : r.normals[i];
  return out;
}

}  // namespace gps
