#include "view/snap_point.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gps {

namespace {

// The parameter s ∈ [0, 1] of the point of segment a + s (b − a) closest to the line o + t d (d unit).
double closest_on_segment(const Vec3& a, const Vec3& b, const Vec3& o, const Vec3& d) {
  const Vec3 e = b - a, w = a - o;
  const double ee = e.dot(e), ed = e.dot(d), ew = e.dot(w), dw = d.dot(w);
  const double denominator = ee - ed * ed;  // |e|² |d|² − (e·d)², |d| = 1
  if (!(denominator > 1e-300)) return 0.0;  // parallel to the ray: either end is as near
  return std::clamp((ed * dw - ew) / denominator, 0.0, 1.0);
}

// The ray parameter where o + t d meets triangle abc (Möller–Trumbore); infinity where it misses.
double ray_triangle(const Vec3& o, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a, p = d.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < 1e-300) return std::numeric_limits<double>::infinity();
  const Vec3 s = o - a;
  const double u = s.dot(p) / det;
  const Vec3 q = s.cross(e1);
  const double v = d.dot(q) / det;
  if (u < 0.0 || v < 0.0 || u + v > 1.0) return std::numeric_limits<double>::infinity();
  const double t = e2.dot(q) / det;
  return t > 0.0 ? t : std::numeric_limits<double>::infinity();
}

}  // namespace

const char* snap_target_name(SnapTarget target) {
  switch (target) {
    case SnapTarget::increment:
      return "increment";
    case SnapTarget::vertex:
      return "vertex";
    case SnapTarget::edge:
      return "edge";
    case SnapTarget::face:
      return "face";
  }
  return "";
}

std::optional<SnapPoint> find_snap_point(const CovarianceMesh& mesh, const Viewport& view, glm::vec2 pixel,
                                         SnapTarget target, const std::vector<int>& moving, float radius) {
  std::vector<bool> moves(mesh.n_vertices(), false);
  for (const int v : moving)
    if (v >= 0 && size_t(v) < moves.size()) moves[size_t(v)] = true;
  switch (target) {
    case SnapTarget::increment:
      return std::nullopt;
    case SnapTarget::vertex: {
      NearestProjected nearest(view.camera, view.width, view.height, pixel, radius, 0.5f);
      for (size_t v = 0; v < mesh.n_vertices(); ++v)
        if (!moves[v]) nearest.consider(int(v), mesh.mean(v));
      if (nearest.best() < 0) return std::nullopt;
      return SnapPoint{mesh.mean(size_t(nearest.best())), "vertex " + std::to_string(nearest.best())};
    }
    case SnapTarget::edge: {
      const Ray ray = pixel_ray(view.camera, view.width, view.height, pixel);
      const Vec3 o = to_vec(ray.origin), d = to_vec(ray.direction);
      std::optional<SnapPoint> best;
      float best_distance = radius;
      for (size_t e = 0; e < mesh.n_edges(); ++e) {
        const auto [a, b] = mesh.edge(e);
        if (moves[size_t(a)] || moves[size_t(b)]) continue;
        const Vec3 pa = mesh.mean(size_t(a)), pb = mesh.mean(size_t(b));
        const Vec3 point = pa + closest_on_segment(pa, pb, o, d) * (pb - pa);
        const auto at = visible_pixel(view.camera, view.width, view.height, point);
        if (!at) continue;
        const float distance = glm::length(glm::vec2(*at) - (pixel + glm::vec2(0.5f)));  // from the pixel's centre
        if (distance > best_distance) continue;
        best_distance = distance;
        best = SnapPoint{point, "edge " + std::to_string(std::min(a, b)) + "–" + std::to_string(std::max(a, b))};
      }
      return best;
    }
    case SnapTarget::face: {
      const Ray ray = pixel_ray(view.camera, view.width, view.height, pixel);
      const Vec3 o = to_vec(ray.origin), d = to_vec(ray.direction);
      double best_t = std::numeric_limits<double>::infinity();
      int best_face = -1;
      for (size_t f = 0; f < mesh.n_faces(); ++f) {
        const std::span<const int> corners = mesh.face(f);
        if (std::any_of(corners.begin(), corners.end(), [&](int v) { return moves[size_t(v)]; })) continue;
        for (size_t k = 1; k + 1 < corners.size(); ++k) {
          const double t = ray_triangle(o, d, mesh.mean(size_t(corners[0])), mesh.mean(size_t(corners[k])),
                                        mesh.mean(size_t(corners[k + 1])));
          if (t < best_t) best_t = t, best_face = int(f);
        }
      }
      if (best_face < 0) return std::nullopt;
      return SnapPoint{o + best_t * d, "face " + std::to_string(best_face)};
    }
  }
  return std::nullopt;
}

}  // namespace gps
