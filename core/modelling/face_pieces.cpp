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

// Whether the triangle a, b, c has no area as seen along `normal`: its corners on one line, within
// rounding of its size.
bool flat_triangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& normal) {
  const double longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  return std::abs((b - a).cross(c - a).dot(normal)) <= 1e-12 * longest * normal.norm();
}

// The corner of `piece` whose ear (it and its two neighbours) has the shortest diagonal among the
// convex ears holding no other corner, tried from corner 1 on: an ear with area where there is one
// (corners on one line, as a bevel's straight profile puts them, make ears without), else one
// without; corner 1 where none is.
size_t best_ear(const std::vector<int>& piece, const std::vector<Vec3>& means, const Vec3& normal) {
  const size_t n = piece.size();
  size_t best = 1;
  double shortest = std::numeric_limits<double>::infinity();
  bool best_flat = true;
  for (size_t step = 1; step <= n; ++step) {
    const size_t k = step % n;
    const Vec3 &a = means[size_t(piece[(k + n - 1) % n])], &b = means[size_t(piece[k])],
               &c = means[size_t(piece[(k + 1) % n])];
    if (!((b - a).cross(c - b).dot(normal) > 0)) continue;
    bool empty = true;
    for (size_t other = 0; other < n && empty; ++other)
      if (other != k && other != (k + 1) % n && other != (k + n - 1) % n)
        empty = !in_triangle(means[size_t(piece[other])], a, b, c, normal);
    if (!empty) continue;
    const bool flat = flat_triangle(a, b, c, normal);
    const double diagonal = (c - a).squaredNorm();
    if ((best_flat && !flat) || (flat == best_flat && diagonal < shortest))
      shortest = diagonal, best = k, best_flat = flat;
  }
  return best;
}

// Ear clipping of `piece` into `triangles`.
void clip_ears(std::vector<int> rest, const std::vector<Vec3>& means, const Vec3& normal,
               std::vector<std::vector<int>>& triangles) {
  while (rest.size() > 3) {
    const size_t n = rest.size(), k = best_ear(rest, means, normal);
    const size_t before = (k + n - 1) % n, after = (k + 1) % n;
    triangles.push_back({rest[before], rest[k], rest[after]});
    // The rest from the ear's far corner round to its near one.
    std::vector<int> next;
    for (size_t i = 0; i + 1 < n; ++i) next.push_back(rest[(after + i) % n]);
    rest = std::move(next);
  }
  triangles.push_back(std::move(rest));
}

// Whether corner k of `piece` lies on the straight line between its neighbours (a bevel's straight
// profile or a cut along an edge puts corners there): any triangle with it and its neighbours has no area.
bool straight_corner(const std::vector<int>& piece, size_t k, const std::vector<Vec3>& means, const Vec3& normal) {
  const size_t n = piece.size();
  const Vec3 &a = means[size_t(piece[(k + n - 1) % n])], &b = means[size_t(piece[k])],
             &c = means[size_t(piece[(k + 1) % n])];
  return flat_triangle(a, b, c, normal) && (a - b).dot(c - b) < 0;
}

}  // namespace

void triangulate_pieces(std::vector<std::vector<int>>& pieces, const std::vector<Vec3>& means, const Vec3& normal) {
  for (size_t p = 0, count = pieces.size(); p < count; ++p) {
    const std::vector<int>& piece = pieces[p];
    if (piece.size() <= 3) continue;
    // The corners on straight lines set aside (every triangle through them and both their neighbours
    // would have no area), the rest clipped, then each straight run fanned from the far corner of the
    // triangle on its line: (a, c, d) with a, p₁ … p_k, c in line becomes (a, p₁, d) … (p_k, c, d).
    std::vector<int> corners;
    std::vector<std::vector<int>> runs;  // by corner kept: the straight corners after it
    for (size_t k = 0; k < piece.size(); ++k) {
      if (corners.empty() || !straight_corner(piece, k, means, normal)) {
        corners.push_back(piece[k]);
        runs.emplace_back();
      } else {
        runs.back().push_back(piece[k]);
      }
    }
    // Straight corners before the first kept one belong to the last kept one's run.
    if (!runs.empty() && corners.size() > 1 && straight_corner(piece, 0, means, normal)) {
      runs.back().push_back(corners.front());
      runs.back().insert(runs.back().end(), runs.front().begin(), runs.front().end());
      corners.erase(corners.begin());
      runs.erase(runs.begin());
    }
    std::vector<std::vector<int>> triangles;
    if (corners.size() < 3) {  // no area at all: clipped as it is
      clip_ears(piece, means, normal, triangles);
    } else {
      clip_ears(corners, means, normal, triangles);
      for (size_t i = 0; i < corners.size(); ++i) {
        if (runs[i].empty()) continue;
        const int a = corners[i], c = corners[(i + 1) % corners.size()];
        for (std::vector<int>& t : triangles) {
          const size_t at = size_t(std::find(t.begin(), t.end(), a) - t.begin());
          if (at == 3 || t[(at + 1) % 3] != c) continue;
          const int d = t[(at + 2) % 3];
          std::vector<int> line{a};
          line.insert(line.end(), runs[i].begin(), runs[i].end());
          line.push_back(c);
          t = {line[0], line[1], d};
          for (size_t k = 1; k + 1 < line.size(); ++k) triangles.push_back({line[k], line[k + 1], d});
          break;
        }
      }
    }
    pieces[p] = triangles[0];
    pieces.insert(pieces.end(), triangles.begin() + 1, triangles.end());
  }
}

}  // namespace gps
