#include "render/comparison/reference_triangles.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>

#include "core/support/error.h"
#include "core/reference/reference_subdivision.h"
#include "render/comparison/patch_triangles.h"

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

SubdivisionResult reference(const CovarianceMesh& mesh, int levels, const PlanOptions& options) {
  return subdivide(mesh, {scheme_for(mesh.topology(), options), levels, true, options.loop_beta, true});
}
}  // namespace

TriangleMesh reference_triangles(const CovarianceMesh& mesh, int levels, const PlanOptions& options) {
  const SubdivisionResult r = reference(mesh, levels, options);
  const PolygonTopology& t = r.mesh.topology();
  TriangleMesh out;
  out.positions.resize(r.mesh.n_vertices());
  for (size_t i = 0; i < out.positions.size(); ++i) out.positions[i] = r.mesh.mean(i);
  out.normals = r.normals;
  const bool quad_cells = r.corner_params.size() == t.verts.size();
  for (int f = 0; f < t.n_faces(); ++f) {
    const int o = t.offsets[size_t(f)], n = t.face_size(f);
    const int first = n == 4 && quad_cells ? corner_nearest_centre(&r.corner_params[size_t(o)]) : 0;
    const auto corner = [&](int k) { return t.verts[size_t(o + (first + k) % n)]; };
    for (int k = 1; k + 1 < n; ++k) out.triangles.push_back({corner(0), corner(k), corner(k + 1)});
  }
  fill_missing_normals(out);
  return out;
}

TriangleMesh reference_in_patch_triangles(SurfaceRenderer& renderer, const CovarianceMesh& mesh, const Camera& camera,
                                          const DrawOptions& o, int width, int height, int levels) {
  const SubdivisionResult r = reference(mesh, levels, {Scheme::catmull_clark});
  const PolygonTopology& t = r.mesh.topology();
  const double steps = std::ldexp(1.0, levels);  // grid points per patch edge
  const auto key = [steps](int patch, double u, double v) {
    return (int64_t(patch) << 40) | (int64_t(std::lround(u * steps)) << 20) | int64_t(std::lround(v * steps));
  };
  // Every grid point of a patch is a corner of one of the reference's faces in that patch.
  std::unordered_map<int64_t, int> vertex_at;
  for (size_t c = 0; c < r.corner_params.size(); ++c) {
    const PatchParam& p = r.corner_params[c];
    vertex_at.emplace(key(p.patch, p.u, p.v), t.verts[c]);
  }
  return patch_triangles(renderer, camera, o, width, height, [&](int patch, double u, double v) {
    const auto at = vertex_at.find(key(patch, u, v));
    if (at == vertex_at.end() || std::abs(u * steps - std::round(u * steps)) > 1e-4 ||
        std::abs(v * steps - std::round(v * steps)) > 1e-4)
      throw Error("the reference at level " + std::to_string(levels) + " has no vertex at patch " +
                  std::to_string(patch) + " (" + std::to_string(u) + ", " + std::to_string(v) +
                  "): draw the patches at level 2^" + std::to_string(levels));
    return SurfaceValues{r.mesh.mean(size_t(at->second)), r.normals[size_t(at->second)]};
  });
}

}  // namespace gps
