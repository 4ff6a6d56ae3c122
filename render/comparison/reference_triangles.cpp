#include "render/comparison/reference_triangles.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/support/error.h"
#include "core/reference/reference_subdivision.h"
#include "core/reference/subdivision_size.h"
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

// What the reference holds beside subdivide()'s own result, in multiples of subdivision_size()'s bytes:
// the parameters of every corner and vertex, the limit normals and tangents, and the triangles drawn
// (measured: 2.5 to 2.9 times at levels 3 and 4 of a 9,600-face sphere).
constexpr double kReferenceBytesOverSubdivision = 3.2;

// The reference of the mesh moved by −origin, its evaluation origin: the refined means keep the
// digits of the mesh's own size where world coordinates far away would lose them.
SubdivisionResult reference(const CovarianceMesh& mesh, int levels, const PlanOptions& options, const Vec3& origin) {
  const SubdivisionOptions subdivision{scheme_for(mesh.topology(), options), levels, true, options.loop_beta, true};
  OutputSize size = subdivision_size(mesh, subdivision);
  size.bytes *= kReferenceBytesOverSubdivision;
  check_output_size(size, "the reference at level " + std::to_string(levels), "faces", "use a lower level");
  if (origin.isZero()) return subdivide(mesh, subdivision);
  CovarianceMesh about = mesh;
  for (size_t v = 0; v < about.n_vertices(); ++v) about.set_mean(v, mesh.mean(v) - origin);
  return subdivide(about, subdivision);
}
}  // namespace

PlacedTriangles reference_triangles(const CovarianceMesh& mesh, int levels, const PlanOptions& options) {
  const Vec3 origin = evaluation_origin(mesh);
  const SubdivisionResult r = reference(mesh, levels, options, origin);
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
  return {std::move(out), origin};
}

PlacedTriangles reference_in_patch_triangles(SurfaceRenderer& renderer, const CovarianceMesh& mesh,
                                             const Camera& camera, const DrawOptions& o, int width, int height,
                                             int levels) {
  const Vec3 origin = evaluation_origin(mesh);
  const SubdivisionResult r = reference(mesh, levels, {Scheme::catmull_clark}, origin);
  const PolygonTopology& t = r.mesh.topology();
  const int steps = 1 << levels, grid = steps + 1;  // grid points per patch edge
  // Every grid point of a patch is a corner of one of the reference's faces in that patch: its vertex,
  // by patch and grid point (−1: none yet), an int each.
  int patches = 0;
  for (const PatchParam& p : r.corner_params) patches = std::max(patches, p.patch + 1);
  std::vector<int> vertex_at(size_t(patches) * size_t(grid) * size_t(grid), -1);
  const auto slot = [&](int patch, long i, long j) {
    return (size_t(patch) * size_t(grid) + size_t(i)) * size_t(grid) + size_t(j);
  };
  for (size_t c = 0; c < r.corner_params.size(); ++c) {
    const PatchParam& p = r.corner_params[c];
    const long i = std::lround(p.u * steps), j = std::lround(p.v * steps);
    if (p.patch < 0 || i < 0 || i > steps || j < 0 || j > steps) continue;
    if (int& at = vertex_at[slot(p.patch, i, j)]; at < 0) at = t.verts[c];
  }
  const auto reference_at = [&](int patch, double u, double v) {
    const long i = std::lround(u * steps), j = std::lround(v * steps);
    const bool on_grid = std::abs(u * steps - double(i)) <= 1e-4 && std::abs(v * steps - double(j)) <= 1e-4 &&
                         patch >= 0 && patch < patches && i >= 0 && i <= steps && j >= 0 && j <= steps;
    const int at = on_grid ? vertex_at[slot(patch, i, j)] : -1;
    if (at < 0)
      throw Error("the reference at level " + std::to_string(levels) + " has no vertex at patch " +
                  std::to_string(patch) + " (" + std::to_string(u) + ", " + std::to_string(v) +
                  "): draw the patches at level 2^" + std::to_string(levels));
    return SurfaceValues{r.mesh.mean(size_t(at)), r.normals[size_t(at)]};
  };
  return {patch_triangles(renderer, camera, o, width, height, reference_at), origin};
}

}  // namespace gps
