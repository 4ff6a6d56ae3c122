#include "core/modelling/samples.h"

#include <cmath>
#include <functional>
#include <map>
#include <numbers>

#include "core/support/error.h"
#include "core/mesh/inference.h"
#include "core/modelling/shapes.h"
#include "core/reference/loop.h"

namespace gps {

namespace {

using Faces = std::vector<std::vector<int>>;

CovarianceMesh isotropic_mesh(const std::vector<Vec3>& points, const Faces& faces, const std::string& name) {
  CovarianceMesh m = make_covariance_mesh(points, std::vector<Mat3>(points.size(), Mat3::Identity()), faces, name);
  isotropic_covariances(m);
  return m;
}

CovarianceMesh isotropic_mesh(const Shape& shape, const std::string& name) {
  return isotropic_mesh(shape.points, shape.faces, name);
}

// Preiner's cone: apex (0, 1.5, 0), 8 vertices on a circle of radius 2 at y = −1.5, open bottom,
// Σ = 0.01·I everywhere but at the apex.
CovarianceMesh cone(const Mat3& apex) {
  const Shape s = cone_shape(8, 2.0, 1.5, -1.5, false);
  std::vector<Mat3> cov(s.points.size(), 0.01 * Mat3::Identity());
  cov[0] = apex;
  return make_covariance_mesh(s.points, cov, s.faces, "cone");
}

Mat3 diag(double x, double y, double z) { return Vec3(x, y, z).asDiagonal(); }

// The boundary of a set of unit voxels on an integer lattice, as outward quads.
CovarianceMesh voxel_surface(const std::function<bool(int, int, int)>& filled, int size, double scale,
                             const std::string& name) {
  std::map<std::array<int, 3>, int> index;
  std::vector<Vec3> p;
  Faces f;
  const auto vertex = [&](int x, int y, int z) {
    const auto [it, added] = index.try_emplace({x, y, z}, int(p.size()));
    if (added) p.emplace_back(scale * (x - size / 2.0), scale * (y - size / 2.0), scale * (z - size / 2.0));
    return it->second;
  };
  const auto inside = [&](int x, int y, int z) {
    return x >= 0 && y >= 0 && z >= 0 && x < size && y < size && z < size && filled(x, y, z);
  };
  for (int x = 0; x < size; ++x)
    for (int y = 0; y < size; ++y)
      for (int z = 0; z < size; ++z) {
        if (!inside(x, y, z)) continue;
        for (int axis = 0; axis < 3; ++axis)
          for (const int side : {0, 1}) {
            std::array<int, 3> n = {x, y, z};
            n[size_t(axis)] += side ? 1 : -1;
            if (inside(n[0], n[1], n[2])) continue;
            // The face square on plane axis = c + side, corners ordered counter-clockwise seen from outside.
            const int u = (axis + 1) % 3, w = (axis + 2) % 3;
            std::array<int, 3> c = {x, y, z};
            c[size_t(axis)] += side;
            std::vector<int> quad;
            const int du[4] = {0, 1, 1, 0}, dw[4] = {0, 0, 1, 1};
            for (int k = 0; k < 4; ++k) {
              const int kk = side ? k : (4 - k) % 4;
              std::array<int, 3> q = c;
              q[size_t(u)] += du[kk];
              q[size_t(w)] += dw[kk];
              quad.push_back(vertex(q[0], q[1], q[2]));
            }
            f.push_back(quad);
          }
      }
  return isotropic_mesh(p, f, name);
}

// The edges of a cube as square beams: 8 corner and 12 edge voxels of a 3×3×3 block (genus 5).
CovarianceMesh wirecube() {
  return voxel_surface([](int x, int y, int z) { return (x != 1) + (y != 1) + (z != 1) >= 2; }, 3, 2.0 / 3.0,
                       "wirecube");
}

// n quad sectors, each a k×k grid, around one centre vertex of valence n, on a dome; open boundary.
CovarianceMesh valence(int n) {
  const int k = 3;
  std::vector<Vec3> p = {{0, 0, 0}};
  std::vector<std::vector<int>> spoke(size_t(n), std::vector<int>(size_t(k + 1), 0));
  const auto dir = [&](int s) {
    return Vec3(std::cos(2 * std::numbers::pi * s / n), std::sin(2 * std::numbers::pi * s / n), 0);
  };
  const auto lift = [&](Vec3 x) {
    x.z() = 0.4 * (1.0 - x.squaredNorm() / (2.0 * k * k));
    return x;
  };
  for (int s = 0; s < n; ++s)
    for (int a = 1; a <= k; ++a) {
      spoke[size_t(s)][size_t(a)] = int(p.size());
      p.push_back(lift(double(a) * dir(s)));
    }
  Faces f;
  for (int s = 0; s < n; ++s) {
    const int t = (s + 1) % n;
    std::vector<std::vector<int>> id(size_t(k + 1), std::vector<int>(size_t(k + 1), 0));
    for (int a = 0; a <= k; ++a)
      for (int b = 0; b <= k; ++b) {
        if (b == 0)
          id[size_t(a)][0] = spoke[size_t(s)][size_t(a)];
        else if (a == 0)
          id[0][size_t(b)] = spoke[size_t(t)][size_t(b)];
        else {
          id[size_t(a)][size_t(b)] = int(p.size());
          // Polar layout: radius max(a, b), angle between the two spokes, so the mesh is a disc.
          const double angle = 2 * std::numbers::pi * (s + double(b) / (a + b)) / n;
          p.push_back(lift(std::max(a, b) * Vec3(std::cos(angle), std::sin(angle), 0)));
        }
      }
    for (int a = 0; a < k; ++a)
      for (int b = 0; b < k; ++b)
        f.push_back({id[size_t(a)][size_t(b)], id[size_t(a + 1)][size_t(b)], id[size_t(a + 1)][size_t(b + 1)],
                     id[size_t(a)][size_t(b + 1)]});
  }
  return isotropic_mesh(p, f, "valence" + std::to_string(n));
}

// A bumpy n×n quad grid over [−1, 1]² with about `size` faces.
CovarianceMesh grid(int size) {
  const int n = std::max(1, int(std::lround(std::sqrt(double(size)))));
  std::vector<Vec3> p;
  p.reserve(size_t(n + 1) * size_t(n + 1));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = -1 + 2.0 * i / n, y = -1 + 2.0 * j / n;
      p.emplace_back(x, y, 0.15 * std::sin(3 * x) * std::cos(2 * y));
    }
  Faces f;
  f.reserve(size_t(n) * size_t(n));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      f.push_back({a, a + 1, a + n + 2, a + n + 1});
    }
  return isotropic_mesh(p, f, "grid");
}

// A cube whose faces are m×m grids, projected to the unit sphere: about `size` quads, 8 valence-3 vertices.
CovarianceMesh sphere(int size) {
  const int m = std::max(1, int(std::lround(std::sqrt(size / 6.0))));
  return isotropic_mesh(cube_sphere_shape(m), "sphere");
}

// An icosahedron refined by midpoint splits (Loop's topology) and projected to the unit sphere:
// 20·4^k triangles, the k nearest to `size`; 12 vertices of valence 5, every other of valence 6.
CovarianceMesh icosphere(int size) {
  const double g = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vec3> p = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                         {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  PolygonTopology t;
  t.n_vertices = 12;
  for (const int v :
       {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4,  11, 10, 2,  10, 7, 6, 7, 1, 8,
        3, 9,  4, 3, 4, 2, 3, 2, 6, 3, 6, 8,  3, 8,  9,  4, 9, 5, 2, 4,  11, 6,  2,  10, 8,  6, 7, 9, 8, 1}) {
    t.verts.push_back(v);
    if (t.verts.size() % 3 == 0) t.offsets.push_back(int(t.verts.size()));
  }
  const int levels = std::max(0, int(std::lround(std::log(std::max(size, 20) / 20.0) / std::log(4.0))));
  for (int level = 0; level < levels; ++level) {
    const MeshConnectivity c = connectivity_of(t);
    for (int e = 0; e < c.n_edges(); ++e)
      p.push_back(0.5 * (p[size_t(c.edge_verts[2 * size_t(e)])] + p[size_t(c.edge_verts[2 * size_t(e) + 1])]));
    t = loop_topology(t, c);
  }
  for (auto& x : p) x.normalize();
  Faces f(size_t(t.n_faces()));
  for (int i = 0; i < t.n_faces(); ++i)
    f[size_t(i)].assign(t.verts.begin() + t.offsets[size_t(i)], t.verts.begin() + t.offsets[size_t(i) + 1]);
  return isotropic_mesh(p, f, "icosphere");
}

// A chess pawn turned on a lathe: a profile of 24 (radius, height) points between the two poles,
// revolved in 32 sectors, covariances inferred (GPS paper Eq. 16–17). The 23 bands are quads; at
// each pole a fan of 32 triangles, or, for `quads_only`, 16 quads that each join two neighbouring
// fan triangles (the same mesh without triangles: 768 quads against 736 quads and 64 triangles).
CovarianceMesh pawn(bool quads_only) {
  const double profile[24][2] = {{0.50, 0.00}, {0.55, 0.02}, {0.56, 0.07}, {0.54, 0.11}, {0.47, 0.14}, {0.42, 0.17},
                                 {0.40, 0.21}, {0.35, 0.24}, {0.28, 0.28}, {0.23, 0.36}, {0.20, 0.46}, {0.18, 0.56},
                                 {0.17, 0.64}, {0.24, 0.67}, {0.27, 0.70}, {0.22, 0.73}, {0.16, 0.75}, {0.20, 0.79},
                                 {0.23, 0.85}, {0.24, 0.91}, {0.22, 0.98}, {0.17, 1.04}, {0.11, 1.08}, {0.05, 1.10}};
  const int sectors = 32, rings = 24;
  std::vector<Vec3> p = {{0, 0, 0}};
  for (const auto& [r, y] : profile)
    for (int k = 0; k < sectors; ++k)
      p.emplace_back(r * std::cos(2 * std::numbers::pi * k / sectors), y,
                     -r * std::sin(2 * std::numbers::pi * k / sectors));
  p.emplace_back(0, 1.11, 0);
  const int top = int(p.size()) - 1;
  const auto at = [&](int ring, int k) { return 1 + ring * sectors + (k % sectors); };
  Faces f;
  const int fan_step = quads_only ? 2 : 1;
  for (int k = 0; k < sectors; k += fan_step)  // bottom pole, outward normals point down
    f.push_back(quads_only ? std::vector<int>{0, at(0, k + 2), at(0, k + 1), at(0, k)}
                           : std::vector<int>{0, at(0, k + 1), at(0, k)});
  for (int ring = 0; ring + 1 < rings; ++ring)
    for (int k = 0; k < sectors; ++k) f.push_back({at(ring, k), at(ring, k + 1), at(ring + 1, k + 1), at(ring + 1, k)});
  for (int k = 0; k < sectors; k += fan_step)
    f.push_back(quads_only ? std::vector<int>{top, at(rings - 1, k), at(rings - 1, k + 1), at(rings - 1, k + 2)}
                           : std::vector<int>{top, at(rings - 1, k), at(rings - 1, k + 1)});
  CovarianceMesh m =
      make_covariance_mesh(p, std::vector<Mat3>(p.size(), Mat3::Identity()), f, quads_only ? "pawn-quads" : "pawn");
  infer_covariances(m);
  return m;
}

struct Sample {
  std::string name, description;
  std::function<CovarianceMesh(int)> make;
};

const std::vector<Sample>& samples() {
  static const std::vector<Sample> list = [] {
    std::vector<Sample> s = {
        {"cube", "8 vertices, 6 quads, isotropic", [](int) { return isotropic_mesh(cube_shape(), "cube"); }},
        {"cone", "Preiner's cone: 8 triangles, open bottom, covariance 0.01 I",
         [](int) { return cone(0.01 * Mat3::Identity()); }},
        {"cone-pointy", "cone with apex covariance 1e-5 I: a sharp tip",
         [](int) { return cone(1e-5 * Mat3::Identity()); }},
        {"cone-concave",
         "cone with apex covariance diag(1e-5, 1e-3, 1e-5), a needle along the axis: a tip with concave flanks",
         [](int) { return cone(diag(1e-5, 1e-3, 1e-5)); }},
        {"cone-plateau", "cone with apex covariance diag(1e-3, 1e-5, 1e-3), a flat disc: a plateau",
         [](int) { return cone(diag(1e-3, 1e-5, 1e-3)); }},
        {"cone-cylinder", "cone with apex covariance diag(0.1, 1e-5, 0.1), a disc wider than the base: a cylinder",
         [](int) { return cone(diag(0.1, 1e-5, 0.1)); }},
        {"cylinder", "capped cylinder: 16 quads and two octagons",
         [](int) { return isotropic_mesh(cylinder_shape(8, 3, 1.0, -1.0, 1.0), "cylinder"); }},
        {"wirecube", "the edges of a cube as square beams: genus-5 quad mesh", [](int) { return wirecube(); }},
    };
    for (int n = 3; n <= 10; ++n)
      s.push_back({"valence" + std::to_string(n),
                   "quad mesh with one extraordinary vertex of valence " + std::to_string(n),
                   [n](int) { return valence(n); }});
    s.push_back({"torus", "24 x 12 quads", [](int) { return isotropic_mesh(torus_shape(24, 12, 2.0, 0.7), "torus"); }});
    s.push_back({"grid", "bumpy quad grid with boundary; --size sets the face count (default 1024)",
                 [](int size) { return grid(size > 0 ? size : 1024); }});
    s.push_back({"sphere", "cube-sphere of quads, 8 valence-3 vertices; --size sets the face count (default 1536)",
                 [](int size) { return sphere(size > 0 ? size : 1536); }});
    s.push_back({"icosphere",
                 "subdivided icosahedron of triangles (Loop), 12 valence-5 vertices; --size sets the face count, "
                 "20·4^k (default 1280)",
                 [](int size) { return icosphere(size > 0 ? size : 1280); }});
    s.push_back({"pawn",
                 "chess pawn turned on a lathe: 736 quads, triangle fans at the poles (64), inferred covariances",
                 [](int) { return pawn(false); }});
    s.push_back({"pawn-quads", "the pawn with each pair of pole triangles joined into a quad: 768 quads",
                 [](int) { return pawn(true); }});
    return s;
  }();
  return list;
}

}  // namespace

std::vector<std::string> sample_names() {
  std::vector<std::string> names;
  for (const auto& s : samples()) names.push_back(s.name);
  return names;
}

std::string sample_description(const std::string& name) {
  for (const auto& s : samples())
    if (s.name == name) return s.description;
  return {};
}

CovarianceMesh make_sample(const std::string& name, int size) {
  if (size < 0 || size > 4'000'000)
    throw usage_error("sample size must be 1..4000000 faces, got " + std::to_string(size));
  for (const auto& s : samples())
    if (s.name == name) return s.make(size);
  std::string known;
  for (const auto& s : samples()) known += (known.empty() ? "" : ", ") + s.name;
  throw usage_error("unknown sample '" + name + "' (known: " + known + ")");
}

bool sample_has_size(const std::string& name) { return name == "grid" || name == "sphere" || name == "icosphere"; }

}  // namespace gps
