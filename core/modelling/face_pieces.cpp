#include "core/modelling/face_pieces.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>

namespace gps {

bool split_along(std::vector<std::vector<int>>& pieces, const std::vector<int>& cut) {
  if (cut.size() < 2 || cut.front() == cut.back()) return false;
  for (std::vector<int>& piece : pieces) {
    const auto ix = std::find(piece.begin(), piece.end(), cut.front());
    const auto iy = std::find(piece.begin(), piece.end(), cut.back());
    if (ix == piece.end() || iy == piece.end()) continue;
    size_t i = size_t(ix - piece.begin()), j = size_t(iy - piece.begin());
    std::vector<int> inner(cut.begin() + 1, cut.end() - 1);  // from corner i to corner j
    if (i > j) {
      std::swap(i, j);
      std::reverse(inner.begin(), inner.end());
    }
    if (inner.empty() && (j - i < 2 || (i == 0 && j + 1 == piece.size()))) continue;
    // Corner i to corner j along the cycle and back along the cut; corner j to corner i, then the cut.
    std::vector<int> rest(piece.begin() + long(j), piece.end());
    rest.insert(rest.end(), piece.begin(), piece.begin() + long(i) + 1);
    rest.insert(rest.end(), inner.begin(), inner.end());
    std::vector<int> kept(piece.begin() + long(i), piece.begin() + long(j) + 1);
    kept.insert(kept.end(), inner.rbegin(), inner.rend());
    piece = std::move(kept);
    pieces.push_back(std::move(rest));
    return true;
  }
  return false;
}

namespace {

// Whether p lies inside or on the triangle a, b, c as seen along `normal`.
bool in_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& normal) {
  return (b - a).cross(p - a).dot(normal) >= 0 && (c - b).cross(p - b).dot(normal) >= 0 &&
         (a - c).cross(p - c).dot(normal) >= 0;
}

// The corner of `piece` whose ear (it and its two neighbours) has the shortest diagonal among the
// convex ears holding no other corner, tried from corner 1 on; corner 1 where none is.
size_t best_ear(const std::vector<int>& piece, const std::vector<Vec3>& means, const Vec3& normal) {
  const size_t n = piece.size();
  size_t best = 1;
  double shortest = std::numeric_limits<double>::infinity();
  for (size_t step = 1; step <= n; ++step) {
    const size_t k = step % n;
    const Vec3 &a = means[size_t(piece[(k + n - 1) % n])], &b = means[size_t(piece[k])],
               &c = means[size_t(piece[(k + 1) % n])];
    if (!((b - a).cross(c - b).dot(normal) > 0)) continue;
    bool empty = true;
    for (size_t other = 0; other < n && empty; ++other)
      if (other != k && other != (k + 1) % n && other != (k + n - 1) % n)
        empty = !in_triangle(means[size_t(piece[other])], a, b, c, normal);
    const double diagonal = (c - a).squaredNorm();
    if (empty && diagonal < shortest) shortest = diagonal, best = k;
  }
  return best;
}

// A triangle whose corner b lies on the edge a–c opposite it (a corner of the polygon on the line of
// its neighbours, which the last ear can leave) has no area: the diagonal a–c is flipped with the
// triangle beyond it, (a, c, d) becoming (a, b, d) and (b, c, d), both with area where d is off the line.
void flip_flat_triangles(std::vector<std::vector<int>>& triangles, const std::vector<Vec3>& means, const Vec3& normal) {
  const auto flat = [&](const std::vector<int>& t) {
    const Vec3 &a = means[size_t(t[0])], &b = means[size_t(t[1])], &c = means[size_t(t[2])];
    const double longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    return std::abs((b - a).cross(c - a).dot(normal)) <= 1e-12 * longest;
  };
  for (size_t i = 0; i < triangles.size(); ++i) {
    if (!flat(triangles[i])) continue;
    // Rotate so that b is the corner on the line: the one opposite the longest edge.
    std::vector<int> t = triangles[i];
    for (int turn = 0; turn < 3; ++turn) {
      const Vec3 &a = means[size_t(t[0])], &b = means[size_t(t[1])], &c = means[size_t(t[2])];
      if ((c - a).squaredNorm() >= std::max((b - a).squaredNorm(), (c - b).squaredNorm())) break;
      std::rotate(t.begin(), t.begin() + 1, t.end());
    }
    const int a = t[0], b = t[1], c = t[2];
    for (size_t j = 0; j < triangles.size(); ++j) {
      const std::vector<int>& o = triangles[j];
      const auto at = std::find(o.begin(), o.end(), a);
      if (j == i || at == o.end() || o[size_t((at - o.begin() + 1) % 3)] != c) continue;
      const int d = o[size_t((at - o.begin() + 2) % 3)];
      const std::vector<int> first{a, b, d}, second{b, c, d};
      if (flat(first) || flat(second)) continue;
      triangles[i] = first;
      triangles[j] = second;
      break;
    }
  }
}

}  // namespace

void triangulate_pieces(std::vector<std::vector<int>>& pieces, const std::vector<Vec3>& means, const Vec3& normal) {
  for (size_t p = 0, count = pieces.size(); p < count; ++p) {
    std::vector<std::vector<int>> triangles;
    std::vector<int> rest = pieces[p];
    while (rest.size() > 3) {
      const size_t n = rest.size(), k = best_ear(rest, means, normal);
      const size_t before = (k + n - 1) % n, after = (k + 1) % n;
      triangles.push_back({rest[before], rest[k], rest[after]});
      // The rest from the ear's far corner round to its near one.
      std::vector<int> next;
      for (size_t i = 0; i + 1 < n; ++i) next.push_back(rest[(after + i) % n]);
      rest = std::move(next);
    }
    if (triangles.empty()) continue;
    triangles.push_back(std::move(rest));
    flip_flat_triangles(triangles, means, normal);
    pieces[p] = triangles[0];
    pieces.insert(pieces.end(), triangles.begin() + 1, triangles.end());
  }
}

}  // namespace gps
