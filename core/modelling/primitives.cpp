#include "core/modelling/primitives.h"

#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <sstream>

#include "core/support/error.h"

namespace gps {

namespace {

constexpr double pi = std::numbers::pi;

// A shape of extent 1 centred at the origin.
struct Shape {
  std::vector<Vec3> points;
  std::vector<std::vector<int>> faces;
};

Shape plane() {
  Shape s;
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 2; ++j) s.points.emplace_back(-0.5 + 0.5 * i, 0, -0.5 + 0.5 * j);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const int v = 3 * i + j;
      s.faces.push_back({v, v + 1, v + 4, v + 3});  // z then x: normal +y
    }
  return s;
}

Shape cube() {
  Shape s;
  s.points = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  for (Vec3& p : s.points) p *= 0.5;
  s.faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
  return s;
}

// A ring of n points of radius r at height y, counter-clockwise seen from +y.
void add_ring(Shape& s, int n, double r, double y) {
  for (int k = 0; k < n; ++k) s.points.emplace_back(r * std::cos(2 * pi * k / n), y, -r * std::sin(2 * pi * k / n));
}

Shape cylinder() {
  const int n = 8;
  Shape s;
  add_ring(s, n, 0.5, -0.5);
  add_ring(s, n, 0.5, 0.5);
  std::vector<int> top, bottom;
  for (int k = 0; k < n; ++k) {
    s.faces.push_back({k, (k + 1) % n, n + (k + 1) % n, n + k});
    top.push_back(n + k);
    bottom.push_back(n - 1 - k);
  }
  s.faces.push_back(top);
  s.faces.push_back(bottom);
  return s;
}

Shape cone() {
  const int n = 8;
  Shape s;
  s.points.emplace_back(0, 0.5, 0);
  add_ring(s, n, 0.5, -0.5);
  std::vector<int> base;
  for (int k = 0; k < n; ++k) {
    s.faces.push_back({0, 1 + k, 1 + (k + 1) % n});
    base.push_back(n - k);
  }
  s.faces.push_back(base);
  return s;
}

// A cube whose faces are 2×2 grids, projected to the sphere of radius 1/2.
Shape sphere() {
  const int m = 2;
  Shape s;
  std::map<std::array<int, 3>, int> index;
  const auto vertex = [&](std::array<int, 3> g) {
    const auto [it, added] = index.try_emplace(g, int(s.points.size()));
    if (added) s.points.push_back(0.5 * Vec3(g[0], g[1], g[2]).normalized());
    return it->second;
  };
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

// Ring radius and tube radius in the ratio of the torus sample, outer diameter 1.
Shape torus() {
  const int nu = 8, nv = 6;
  const double tube = 0.5 * 0.7 / 2.7, ring = 0.5 - tube;
  Shape s;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double a = 2 * pi * i / nu, b = 2 * pi * j / nv;
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

Shape shape_of(Primitive p) {
  switch (p) {
    case Primitive::plane:
      return plane();
    case Primitive::cube:
      return cube();
    case Primitive::cylinder:
      return cylinder();
    case Primitive::cone:
      return cone();
    case Primitive::sphere:
      return sphere();
    case Primitive::torus:
      return torus();
  }
  throw Error("unknown primitive");
}

double mean_edge_length(const Shape& s) {
  double total = 0;
  int count = 0;
  for (const auto& face : s.faces)
    for (size_t k = 0; k < face.size(); ++k) {
      total += (s.points[size_t(face[(k + 1) % face.size()])] - s.points[size_t(face[k])]).norm();
      ++count;
    }
  return total / count;  // each interior edge counted from both sides alike
}

}  // namespace

std::vector<std::string> primitive_names() { return {"plane", "cube", "cylinder", "cone", "sphere", "torus"}; }

std::optional<Primitive> primitive_named(const std::string& name) {
  const std::vector<std::string> names = primitive_names();
  for (size_t k = 0; k < names.size(); ++k)
    if (names[k] == name) return Primitive(k);
  return std::nullopt;
}

std::vector<int> append_primitive(MeshArrays& a, Primitive primitive, const Vec3& center, double size,
                                  std::string& summary) {
  if (!(size > 0) || !std::isfinite(size)) {
    std::ostringstream s;
    s << size;
    throw Error("the size must be positive and finite (got " + s.str() + ")");
  }
  if (!center.allFinite()) throw Error("the centre must be finite");
  const Shape s = shape_of(primitive);
  const double sigma = 0.5 * size * mean_edge_length(s);
  const int offset = a.n_vertices();
  std::vector<int> added;
  for (const Vec3& p : s.points) {
    const int v = a.add_vertex({center + size * p, sigma * sigma * Mat3::Identity()});
    // As build_mesh would name it: the first of the mesh's vertices with a problem is a new one.
    std::string why = position_problem(a.means[size_t(v)]);
    if (why.empty()) why = covariance_problem(a.covariances[size_t(v)]);
    if (!why.empty()) throw Error("the result would not be a valid mesh: vertex " + std::to_string(v) + " " + why);
    added.push_back(v);
  }
  for (auto face : s.faces) {
    for (int& v : face) v += offset;
    a.faces.push_back(std::move(face));
  }
  summary = "added a " + primitive_names()[size_t(primitive)] + ": " + std::to_string(s.points.size()) + " vertices, " +
            std::to_string(s.faces.size()) + " faces";
  return added;
}

Modelled add_primitive(const CovarianceMesh& mesh, Primitive primitive, const Vec3& center, double size) {
  MeshArrays a = arrays_of(mesh);
  std::string summary;
  std::vector<int> selection = append_primitive(a, primitive, center, size, summary);
  return {build_mesh(a), std::move(selection), std::move(summary)};
}

PrimitivePlacement primitive_placement(const CovarianceMesh& mesh, const std::vector<int>& selected) {
  if (mesh.n_vertices() == 0) return {Vec3::Zero(), 2.0};
  Vec3 lo = mesh.mean(0), hi = lo;
  for (size_t v = 1; v < mesh.n_vertices(); ++v) {
    lo = lo.cwiseMin(mesh.mean(v));
    hi = hi.cwiseMax(mesh.mean(v));
  }
  const double diagonal = (hi - lo).norm(), extent = (hi - lo).maxCoeff();
  if (!(extent > 0)) return {lo, 2.0};  // a single point
  if (!selected.empty()) {
    Vec3 sum = Vec3::Zero();
    for (const int v : selected) sum += mesh.mean(size_t(v));
    return {sum / double(selected.size()), 0.25 * diagonal};
  }
  const double size = 0.5 * extent;
  return {Vec3(hi.x() + 0.25 * extent + 0.5 * size, 0.5 * (lo.y() + hi.y()), 0.5 * (lo.z() + hi.z())), size};
}

}  // namespace gps
