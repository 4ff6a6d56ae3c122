#include "core/fitting/triangle_pairing.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
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
  const PolygonTopology& t = mesh.topology();
  const MeshConnectivity& connectivity = mesh.connectivity();
  const size_t n_faces = mesh.n_faces();
  std::vector<Candidate> candidates;
  for (size_t e = 0; e < mesh.n_edges(); ++e) {
    if (mesh.is_boundary_edge(e)) continue;
    const int g0 = connectivity.edge_faces[2 * e], g1 = connectivity.edge_faces[2 * e + 1];
    if (mesh.face_size(size_t(g0)) != 3 || mesh.face_size(size_t(g1)) != 3) continue;
    const int p1 = mesh.edge(e)[0], p2 = mesh.edge(e)[1];
    if (mesh.sharpness.crease(p1, p2) > 0) continue;
    // Each triangle's vertex off the edge, and whether the triangle runs the edge p1 → p2 (f0) or back (f1).
    const auto off_edge = [&](int face) {
      const int o = t.offsets[size_t(face)];
      int k = 0;
      while (connectivity.face_edges[size_t(o + k)] != int(e)) ++k;
      return std::pair(t.verts[size_t(o + (k + 2) % 3)], t.verts[size_t(o + k)] == p1);
    };
    auto [p0, runs_up] = off_edge(g0);
    int q = off_edge(g1).first, f0 = g0, f1 = g1;
    if (!runs_up) std::swap(p0, q), std::swap(f0, f1);
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
    candidates.push_back({worst + fold, std::min(f0, f1), std::max(f0, f1), quad});
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& x, const Candidate& y) { return x.score < y.score; });
  std::vector<int> partner(n_faces, -1);
  std::vector<const Candidate*> quad_of(n_faces, nullptr);
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
  faces.reserve(n_faces - quads);
  for (size_t f = 0; f < n_faces; ++f) {
    if (const Candidate* pair = quad_of[f]) {
      faces.emplace_back(pair->corners.begin(), pair->corners.end());
    } else if (partner[f] < 0) {
      const std::span<const int> face = mesh.face(f);
      faces.emplace_back(face.begin(), face.end());
    }
  }
  CovarianceMesh paired = make_covariance_mesh(mesh.means(), mesh.covariances, faces, "the paired mesh");
  paired.sharpness = mesh.sharpness;
  mesh = paired;
  return quads;
}

}  // namespace gps
