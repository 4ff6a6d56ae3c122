#include "core/io/face_triangulation.h"

#include <algorithm>
#include <optional>

#include <Eigen/Geometry>

namespace gps {

namespace {

uint64_t diagonal_key(int a, int b) { return uint64_t(uint32_t(std::min(a, b))) << 32 | uint32_t(std::max(a, b)); }

// The corner of a face to fan its triangles from: the first whose diagonals are free (`is_free`) and
// whose triangles turn as the face does; else the first with free diagonals; else corner 0.
template <class IsFree>
size_t fan_apex(std::span<const int> corners, const std::vector<Vec3>& positions, const Vec3& normal,
                const IsFree& is_free) {
  const size_t n = corners.size();
  std::optional<size_t> untwisted;
  for (size_t apex = 0; apex < n; ++apex) {
    bool free = true, turns = true;
    for (size_t k = 2; k + 1 < n && free; ++k) free = is_free(corners[apex], corners[(apex + k) % n]);
    for (size_t k = 1; k + 1 < n && free && turns; ++k) {
      const Vec3& a = positions[size_t(corners[apex])];
      turns = (positions[size_t(corners[(apex + k) % n])] - a)
                  .cross(positions[size_t(corners[(apex + k + 1) % n])] - a)
                  .dot(normal) > 0;
    }
    if (free && turns) return apex;
    if (free && !untwisted) untwisted = apex;
  }
  return untwisted.value_or(0);
}

// Twice the signed area of the triangle (a, b, c) in the plane: positive where it turns counter-clockwise.
double turn(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const Eigen::Vector2d ab = b - a, ac = c - a;
  return ab.x() * ac.y() - ab.y() * ac.x();
}

}  // namespace

void triangulate_face(const CovarianceMesh& mesh, std::span<const int> corners, const std::vector<Vec3>& positions,
                      const Vec3& normal, Diagonals& diagonals, std::vector<std::array<int, 3>>& out) {
  const size_t n = corners.size();
  const MeshConnectivity& connectivity = mesh.connectivity();
  const auto is_free = [&](int a, int b) {
    return connectivity.find_edge(a, b) < 0 && !diagonals.count(diagonal_key(a, b));
  };
  // The ring of corners not yet cut off, and the corner the next search for an ear starts from.
  std::vector<size_t> before(n), after(n);
  for (size_t k = 0; k < n; ++k) before[k] = (k + n - 1) % n, after[k] = (k + 1) % n;
  size_t left = n, at = 0;
  if (n > 3 && normal.norm() > 0) {
    // The face in its plane, (u, v, normal) right-handed: the face turns counter-clockwise in it.
    const Vec3 axis = normal.normalized(), u = axis.unitOrthogonal(), v = axis.cross(u);
    std::vector<Eigen::Vector2d> p(n);
    for (size_t k = 0; k < n; ++k) {
      const Vec3 d = positions[size_t(corners[k])] - positions[size_t(corners[0])];
      p[k] = {d.dot(u), d.dot(v)};
    }
    const auto convex = [&](size_t k) { return turn(p[before[k]], p[k], p[after[k]]) > 0; };
    // Only a corner that is not convex can lie in an ear; cutting an ear off keeps a convex corner convex
    // in a face that does not cross itself (one that does is checked again as its neighbours change).
    std::vector<size_t> concave;
    std::vector<char> cut(n, 0);
    for (size_t k = 0; k < n; ++k)
      if (!convex(k)) concave.push_back(k);
    const auto is_ear = [&](size_t k) {
      if (!convex(k)) return false;
      const size_t a = before[k], b = after[k];
      return std::none_of(concave.begin(), concave.end(), [&](size_t q) {
        return !cut[q] && q != a && q != k && q != b && turn(p[a], p[k], p[q]) >= 0 && turn(p[k], p[b], p[q]) >= 0 &&
               turn(p[b], p[a], p[q]) >= 0;
      });
    };
    at = 1;  // a convex face is fanned from its first corner, as its ears come in order from corner 1
    while (left > 3) {
      std::optional<size_t> ear, first_ear;
      size_t k = at;
      for (size_t step = 0; step < left && !ear; ++step, k = after[k]) {
        if (!is_ear(k)) continue;
        if (is_free(corners[before[k]], corners[after[k]]))
          ear = k;
        else if (!first_ear)
          first_ear = k;
      }
      if (!ear) ear = first_ear;
      if (!ear) break;
      const size_t a = before[*ear], b = after[*ear];
      out.push_back({corners[a], corners[*ear], corners[b]});
      diagonals.insert(diagonal_key(corners[a], corners[b]));
      after[a] = b, before[b] = a, cut[*ear] = 1, --left, at = b;
      for (const size_t neighbour : {a, b})
        if (!convex(neighbour)) concave.push_back(neighbour);
    }
  }
  // What no ear cut off, from the corner the search stopped at, fanned.
  std::vector<int> rest;
  for (size_t k = at; rest.size() < left; k = after[k]) rest.push_back(corners[k]);
  const size_t apex = left > 3 ? fan_apex(rest, positions, normal, is_free) : 0;
  for (size_t k = 1; k + 1 < left; ++k)
    out.push_back({rest[apex], rest[(apex + k) % left], rest[(apex + k + 1) % left]});
  for (size_t k = 2; k + 1 < left; ++k) diagonals.insert(diagonal_key(rest[apex], rest[(apex + k) % left]));
}

}  // namespace gps
