#include "core/modelling/shapes.h"

#include <array>
#include <cmath>
#include <map>
#include <numbers>

namespace gps {

namespace {

// A ring of n points of radius r at height y, counter-clockwise seen from +y.
void add_ring(Shape& s, int n, double r, double y) {
  for (int k = 0; k < n; ++k)
    s.points.emplace_back(r * std::cos(2 * std::numbers::pi * k / n), y, -r * std::sin(2 * std::numbers::pi * k / n));
}

}  // namespace

Shape cube_shape() {
  Shape s;
  s.points = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  s.faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
  return s;
}

Shape cylinder_shape(int sides, int rings, double radius, double bottom, double spacing) {
  const int n = sides;
  Shape s;
  for (int r = 0; r < rings; ++r) add_ring(s, n, radius, bottom + r * spacing);
  for (int r = 0; r + 1 < rings; ++r)
    for (int k = 0; k < n; ++k)
      s.faces.push_back({r * n + k, r * n + (k + 1) % n, (r + 1) * n + (k + 1) % n, (r + 1) * n + k});
  std::vector<int> top, bottom_cap;
  for (int k = 0; k < n; ++k) top.push_back((rings - 1) * n + k), bottom_cap.push_back(n - 1 - k);
  s.faces.push_back(top);
  s.faces.push_back(bottom_cap);
  return s;
}

Shape cone_shape(int sides, double radius, double apex, double base, bool closed) {
  const int n = sides;
  Shape s;
  s.points.emplace_back(0, apex, 0);
  add_ring(s, n, radius, base);
  for (int k = 0; k < n; ++k) s.faces.push_back({0, 1 + k, 1 + (k + 1) % n});
  if (closed) {
    std::vector<int> base_face;
    for (int k = 0; k < n; ++k) base_face.push_back(n - k);
    s.faces.push_back(base_face);
  }
  return s;
}

Shape polygon_shape(int sides, double radius) {
  Shape s;
  add_ring(s, sides, radius, 0.0);
  s.faces.emplace_back(size_t(sides));
  for (int k = 0; k < sides; ++k) s.faces[0][size_t(k)] = k;
  return s;
}

Shape cube_sphere_shape(int m) {
  Shape s;
  std::map<std::array<int, 3>, int> index;
  const auto vertex = [&](std::array<int, 3> g) {
    const auto [it, added] = index.try_emplace(g, int(s.points.size()));
    if (added) s.points.push_back(Vec3(g[0], g[1], g[2]).normalized());
    return it->second;
  };
  s.faces.reserve(6 * size_t(m) * size_t(m));
  for (int axis = 0; axis < 3; ++axis)
    for (const int side : {-1, 1}) {
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) {
          std::vector<int> quad;
          const int du[4] = {0, 1, 1, 0}, dw[4] = {0, 0, 1, 1};
          for (int k = 0; k < 4; ++k) {
            const int kk = side > 0 ? k : (4 - k) % 4;
            std::array<int, 3> g{};
            g[size_t(axis)] = side * m;
            g[size_t(u)] = -m + 2 * (i + du[kk]);
            g[size_t(w)] = -m + 2 * (j + dw[kk]);
            quad.push_back(vertex(g));
          }
          s.faces.push_back(quad);
        }
    }
  return s;
}

Shape torus_shape(int around, int across, double ring, double tube) {
  const int nu = around, nv = across;
  Shape s;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double a = 2 * std::numbers::pi * i / nu, b = 2 * std::numbers::pi * j / nv;
      s.points.emplace_back((ring + tube * std::cos(b)) * std::cos(a), tube * std::sin(b),
                            (ring + tube * std::cos(b)) * std::sin(a));
    }
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const int i1 = (i + 1) % nu, j1 = (j + 1) % nv;
      s.faces.push_back({i * nv + j, i * nv + j1, i1 * nv + j1, i1 * nv + j});
    }
  return s;
}

}  // namespace gps
