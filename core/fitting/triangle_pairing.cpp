#include "core/fitting/triangle_pairing.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace gps {

namespace {

double degrees_between(const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / M_PI; }

struct Candidate {
  double score;
  int first, second;           // the two triangles, first < second
  std::array<int, 4> corners;  // the quad, in the triangles' orientation
};

}  // namespace

size_t pair_triangles(CovarianceMesh& mesh, const TrianglePairing& limits) {
  const PolyMesh& m = mesh.mesh;
  std::vector<Candidate> candidates;
  for (const auto e : m.edges()) {
    if (m.is_boundary(e)) continue;
    const auto h = m.halfedge_handle(e, 0), o = m.opposite_halfedge_handle(h);
    const auto f0 = m.face_handle(h), f1 = m.face_handle(o);
    if (m.valence(f0) != 3 || m.valence(f1) != 3) continue;
    const int p1 = m.from_vertex_handle(h).idx(), p2 = m.to_vertex_handle(h).idx();
    if (mesh.sharpness.crease(p1, p2) > 0) continue;
    const int p0 = m.to_vertex_handle(m.next_halfedge_handle(h)).idx();
    const int q = m.to_vertex_handle(m.next_halfedge_handle(o)).idx();
    // f0 runs p1 → p2 → p0, f1 runs p2 → p1 → q: the quad p0 → p1 → q → p2 runs as both.
    const std::array<int, 4> quad = {p0, p1, q, p2};
    double worst = 0;
    for (int k = 0; k < 4; ++k) {
      const Vec3 at = mesh.mean(size_t(quad[size_t(k)]));
      const Vec3 next = mesh.mean(size_t(quad[size_t((k + 1) % 4)])) - at;
      const Vec3 previous = mesh.mean(size_t(quad[size_t((k + 3) % 4)])) - at;
      worst = std::max(worst, std::abs(degrees_between(next, previous) - 90.0));
    }
    const Vec3 a = mesh.mean(size_t(p0)), b = mesh.mean(size_t(p1)), c = mesh.mean(size_t(p2)),
               d = mesh.mean(size_t(q));
    const double fold = degrees_between((b - a).cross(c - a), (c - d).cross(b - d));
    if (!(worst <= limits.max_corner_deviation_degrees && fold <= limits.max_fold_degrees)) continue;
    candidates.push_back({worst + fold, std::min(f0.idx(), f1.idx()), std::max(f0.idx(), f1.idx()), quad});
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& x, const Candidate& y) { return x.score < y.score; });
  std::vector<int> partner(m.n_faces(), -1);
  std::vector<const Candidate*> quad_of(m.n_faces(), nullptr);
  size_t quads = 0;
  for (const Candidate& c : candidates) {
    if (partner[size_t(c.first)] >= 0 || partner[size_t(c.second)] >= 0) continue;
    partner[size_t(c.first)] = c.second;
    partner[size_t(c.second)] = c.first;
    quad_of[size_t(c.first)] = &c;
    ++quads;
  }
  if (quads == 0) return 0;
  std::vector<std::vector<int>> faces;
  faces.reserve(m.n_faces() - quads);
  for (const auto f : m.faces()) {
    if (const Candidate* c = quad_of[size_t(f.idx())]) {
      faces.emplace_back(c->corners.begin(), c->corners.end());
    } else if (partner[size_t(f.idx())] < 0) {
      std::vector<int>& face = faces.emplace_back();
      for (const auto v : m.fv_range(f)) face.push_back(v.idx());
    }
  }
  std::vector<Vec3> means(mesh.n_vertices());
  for (size_t v = 0; v < means.size(); ++v) means[v] = mesh.mean(v);
  CovarianceMesh paired = make_covariance_mesh(means, mesh.covariances, faces, "the paired mesh");
  paired.sharpness = mesh.sharpness;
  mesh = paired;
  return quads;
}

}  // namespace gps
