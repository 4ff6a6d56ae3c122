// The repair over random soups that combine every defect class (core/io/mesh_repair.h): closed and
// open parts with cones and tetrahedra on their faces and edges (fins whose extra faces stay joined to
// the kept ones through their other edges), parts glued at a vertex (pinches, with fins on them),
// flipped, duplicated, zero-area and degenerate faces, coincident and isolated vertices. After the
// repair the mesh builds as every command builds it with --repair, and the parts and boundary loops
// the repair reports are those of the built mesh; or the repair names the part it cannot orient.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>

#include "core/io/mesh_io.h"
#include "core/support/error.h"
#include "core/mesh/mesh_connectivity.h"

namespace gps {
namespace {

using Faces = std::vector<std::vector<int>>;

struct RandomSoup {
  std::vector<Vec3> p;
  Faces faces;
  std::vector<int> part_of_vertex;  // the part each vertex was made for
  int parts = 0;
};

int add_vertex(RandomSoup& s, const Vec3& x, int part) {
  s.p.push_back(x);
  s.part_of_vertex.push_back(part);
  return int(s.p.size()) - 1;
}

// A closed octahedron or cube, or an open grid of quads or triangles, oriented, at `at`.
void add_part(RandomSoup& s, std::mt19937& rng, const Vec3& at) {
  const int part = s.parts++;
  const int kind = int(rng() % 4);
  const int base = int(s.p.size());
  if (kind == 0) {
    for (const Vec3& d : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)})
      add_vertex(s, at + d, part);
    for (const auto& f : Faces{{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}})
      s.faces.push_back({base + f[0], base + f[1], base + f[2]});
  } else if (kind == 1) {
    for (int i = 0; i < 8; ++i) add_vertex(s, at + Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1), part);
    for (const auto& f : Faces{{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}})
      s.faces.push_back({base + f[0], base + f[1], base + f[2], base + f[3]});
  } else {
    const int n = 2 + int(rng() % 3);
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) add_vertex(s, at + Vec3(i, j, 0.1 * double(i * j % 3)), part);
    const auto v = [&](int i, int j) { return base + i * (n + 1) + j; };
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        if (kind == 2) {
          s.faces.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)});
        } else {
          s.faces.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1)});
          s.faces.push_back({v(i, j), v(i + 1, j + 1), v(i, j + 1)});
        }
      }
  }
}

template <class T>
const T& pick(const std::vector<T>& items, std::mt19937& rng) {
  return items[rng() % items.size()];
}

Vec3 random_offset(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  return Vec3(u(rng), u(rng), u(rng) + 1.5);
}

// The defects, each applied a random number of times.
void add_defects(RandomSoup& s, std::mt19937& rng) {
  const auto times = [&](int most) { return int(rng() % unsigned(most + 1)); };
  // A cone over a face: each of its edges gets a third face, joined to the others through the cone.
  for (int n = times(2); n > 0; --n) {
    const std::vector<int> f = pick(s.faces, rng);
    Vec3 centre = Vec3::Zero();
    for (const int v : f) centre += s.p[size_t(v)];
    const int apex = add_vertex(s, centre / double(f.size()) + random_offset(rng), s.part_of_vertex[size_t(f[0])]);
    for (size_t k = 0; k < f.size(); ++k) s.faces.push_back({f[(k + 1) % f.size()], f[k], apex});
  }
  // A tetrahedron on an edge of a face: four faces on that edge, each sheet's joined through its others.
  for (int n = times(2); n > 0; --n) {
    const std::vector<int> f = pick(s.faces, rng);
    const size_t k = rng() % f.size();
    const int a = f[k], b = f[(k + 1) % f.size()], part = s.part_of_vertex[size_t(a)];
    const int c = add_vertex(s, s.p[size_t(a)] + random_offset(rng), part);
    const int d = add_vertex(s, s.p[size_t(b)] + random_offset(rng), part);
    s.faces.insert(s.faces.end(), {{b, a, c}, {a, b, d}, {d, b, c}, {c, a, d}});
  }
  // A face on an edge and a vertex of a neighbouring face: fins joined every way.
  for (int n = times(2); n > 0; --n) {
    const std::vector<int> f = pick(s.faces, rng), g = pick(s.faces, rng);
    const size_t k = rng() % f.size();
    const int w = pick(g, rng);
    if (w != f[k] && w != f[(k + 1) % f.size()]) s.faces.push_back({f[k], f[(k + 1) % f.size()], w});
  }
  // Two parts glued at a vertex (a pinch), with a tetrahedron on an edge there now and then.
  for (int n = times(2); n > 0 && s.parts > 1; --n) {
    const std::vector<int> f = pick(s.faces, rng), g = pick(s.faces, rng);
    const int u = pick(f, rng), v = pick(g, rng);
    if (s.part_of_vertex[size_t(u)] == s.part_of_vertex[size_t(v)]) continue;
    for (auto& face : s.faces)
      for (int& x : face)
        if (x == v) x = u;
    if (rng() % 2) {
      const int b = f[size_t(std::find(f.begin(), f.end(), u) - f.begin() + 1) % f.size()];
      const int c = add_vertex(s, s.p[size_t(u)] + random_offset(rng), s.part_of_vertex[size_t(u)]);
      const int d = add_vertex(s, s.p[size_t(b)] + random_offset(rng), s.part_of_vertex[size_t(u)]);
      s.faces.insert(s.faces.end(), {{b, u, c}, {u, b, d}, {d, b, c}, {c, u, d}});
    }
  }
  // Flipped faces, some of them in the sheets of the fins.
  for (auto& face : s.faces)
    if (rng() % 8 == 0) std::reverse(face.begin() + 1, face.end());
  // Duplicates, rotated and perhaps reversed.
  for (int n = times(2); n > 0; --n) {
    std::vector<int> f = pick(s.faces, rng);
    std::rotate(f.begin(), f.begin() + long(rng() % f.size()), f.end());
    if (rng() % 2) std::reverse(f.begin(), f.end());
    s.faces.push_back(f);
  }
  // Zero-area faces: a sliver on an edge through its midpoint, or on three vertices of a line.
  for (int n = times(2); n > 0; --n) {
    const std::vector<int> f = pick(s.faces, rng);
    const int a = f[0], b = f[1];
    const int mid = add_vertex(s, 0.5 * (s.p[size_t(a)] + s.p[size_t(b)]), s.part_of_vertex[size_t(a)]);
    s.faces.push_back({a, mid, b});
  }
  // Degenerate faces and repeated corners.
  for (int n = times(1); n > 0; --n) {
    std::vector<int> f = pick(s.faces, rng);
    f.insert(f.begin() + 1, f[0]);
    s.faces.push_back(f);
    s.faces.push_back({f[0], f[2], f[0]});
  }
  // Coincident vertices: a vertex given again, some of its faces' corners moved to the copy.
  for (int n = times(3); n > 0; --n) {
    const int v = pick(pick(s.faces, rng), rng);
    const int copy = add_vertex(s, s.p[size_t(v)], s.part_of_vertex[size_t(v)]);
    for (auto& face : s.faces)
      for (int& x : face)
        if (x == v && rng() % 2) x = copy;
  }
  // Isolated vertices.
  for (int n = times(1); n > 0; --n) add_vertex(s, random_offset(rng) * 5.0, 0);
}

PolygonSoup soup_of(const RandomSoup& r) {
  PolygonSoup s;
  s.positions = r.p;
  for (const auto& face : r.faces) {
    s.faces.verts.insert(s.faces.verts.end(), face.begin(), face.end());
    s.faces.offsets.push_back(int(s.faces.verts.size()));
  }
  return s;
}

TEST(RepairProperty, RandomSoupsWithEveryDefectBuildWithTheCountsTheRepairReports) {
  constexpr int kSoups = 400;
  std::array<int, kDefectCount> soups_with{};  // per class: the soups that had it
  int built = 0, unorientable = 0;
  for (int seed = 0; seed < kSoups; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937 rng{unsigned(seed)};
    RandomSoup r;
    const int n_parts = 1 + int(rng() % 3);
    for (int i = 0; i < n_parts; ++i) add_part(r, rng, Vec3(4.0 * i, 0.3 * i, 0));
    add_defects(r, rng);
    PolygonSoup repaired = soup_of(r);
    const RepairReport report = repair_polygon_soup(repaired);
    for (int d = 0; d < kDefectCount; ++d) soups_with[size_t(d)] += report.counts[size_t(d)] > 0;
    ImportOptions options;
    options.repair = true;
    RepairReport read_report;
    if (report.count(Defect::unorientable_parts) > 0) {
      ++unorientable;
      try {
        read_mesh_of_soup(soup_of(r), false, "soup.ply", options, &read_report);
        ADD_FAILURE() << "a part that cannot be oriented was read";
      } catch (const Error& e) {
        const std::string face = std::to_string(report.examples[size_t(Defect::unorientable_parts)][0].element);
        EXPECT_NE(std::string(e.what()).find("part that cannot be oriented (Möbius-like), the part of face " + face),
                  std::string::npos)
            << e.what();
      }
      continue;
    }
    // Built as every command builds a mesh it reads with --repair, the covariances inferred.
    const CovarianceMesh m = [&] {
      try {
        return read_mesh_of_soup(soup_of(r), false, "soup.ply", options, &read_report);
      } catch (const Error& e) {
        ADD_FAILURE() << e.what();
        return CovarianceMesh();
      }
    }();
    if (m.n_faces() == 0) continue;
    ++built;
    EXPECT_EQ(read_report.counts, report.counts);
    EXPECT_EQ(int(m.n_faces()), repaired.faces.n_faces());
    EXPECT_EQ(m.n_vertices(), repaired.positions.size());
    const SurfaceCounts counts = surface_counts(m.topology(), m.connectivity());
    EXPECT_EQ(counts.parts, report.parts);
    EXPECT_EQ(counts.boundary_loops, report.boundary_loops);
    EXPECT_EQ(m.topology().verts, repaired.faces.verts) << "the faces as the repair left them";
  }
  // Every class but the unorientable parts came up in many soups; nearly all soups were built.
  for (int d = 0; d < kDefectCount; ++d) {
    if (Defect(d) != Defect::unorientable_parts) {
      EXPECT_GE(soups_with[size_t(d)], kSoups / 10) << "defect " << d;
    }
  }
  EXPECT_GE(built, kSoups * 3 / 4);
  EXPECT_EQ(built + unorientable, kSoups);
}

}  // namespace
}  // namespace gps
