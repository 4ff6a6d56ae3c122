#include "render/reference_triangles.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <memory>
#include <unordered_set>

#include "core/reference_subdivision.h"
#include "render/patch_draw.h"

namespace gps {

namespace {
// Which diagonal splits a quad of the reference: the one through the corner nearest its patch's
// centre, as the tessellator's diagonals run in each quadrant of a patch (Mesa's, after Direct3D's
// reference tessellator: mirrored about the centre). Equal diagonals make equal triangles, so the
// thesis' difference images between the patches and the reference show the surfaces, not the
// triangulations.
// `diagonal` (0: corners 0 and 2, 1: corners 1 and 3; −1: either) keeps the choice to its two ends.
int corner_nearest_centre(const PatchParam* corners, int diagonal = -1) {
  int best = 0;
  double nearest = 1e300;
  for (int k = 0; k < 4; ++k) {
    if (diagonal >= 0 && k % 2 != diagonal) continue;
    const double du = corners[k].u - 0.5, dv = corners[k].v - 0.5, d = du * du + dv * dv;
    if (d < nearest - 1e-12) nearest = d, best = k;
  }
  return best;
}
}  // namespace

TriangleMesh reference_triangles(const CovarianceMesh& mesh, int levels, const PlanOptions& options, const QuadSplit& split) {
  const SubdivisionResult r = subdivide(mesh, {scheme_for(topology_of(mesh.mesh), options), levels, true, options.loop_beta, true});
  const PolygonTopology t = topology_of(r.mesh.mesh);
  TriangleMesh out;
  out.positions.resize(r.mesh.n_vertices());
  for (size_t i = 0; i < out.positions.size(); ++i) out.positions[i] = r.mesh.mean(i);
  std::vector<Vec3> around(out.positions.size(), Vec3::Zero());  // area-weighted face normals
  const bool quad_cells = r.corner_params.size() == t.verts.size();
  for (int f = 0; f < t.n_faces(); ++f) {
    const int o = t.offsets[size_t(f)], n = t.face_size(f);
    const PatchParam* params = &r.corner_params[size_t(o)];
    const int first = n == 4 && quad_cells ? corner_nearest_centre(params, split ? split(params) : -1) : 0;
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

namespace {
// An edge between two tessellation vertices of one patch, their parameters on a grid of 1/1024
// (levels up to 64: the vertices lie on multiples of 1/64), ends in either order.
uint64_t edge_key(int patch, double u0, double v0, double u1, double v1) {
  const auto grid = [](double t) { return uint64_t(std::lround(std::clamp(t, 0.0, 1.0) * 1024.0)); };
  uint64_t a = grid(u0) << 11 | grid(v0), b = grid(u1) << 11 | grid(v1);
  if (a > b) std::swap(a, b);
  return uint64_t(patch) << 44 | a << 22 | b;
}
}  // namespace

QuadSplit tessellator_split(const std::vector<TessellatedVertex>& triangles) {
  auto edges = std::make_shared<std::unordered_set<uint64_t>>();
  for (size_t t = 0; t + 2 < triangles.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      const TessellatedVertex& a = triangles[t + size_t(k)];
      const TessellatedVertex& b = triangles[t + size_t((k + 1) % 3)];
      edges->insert(edge_key(int(a.patch), a.u, a.v, b.u, b.v));
    }
  return [edges](const PatchParam* c) {
    const bool from_first = edges->count(edge_key(c[0].patch, c[0].u, c[0].v, c[2].u, c[2].v)) > 0;
    return from_first ? 0 : 1;
  };
}

}  // namespace gps
