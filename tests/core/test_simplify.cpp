// simplify_mesh: the vertex count asked for, the topology kept (Euler characteristic, boundary loops,
// manifold and consistently oriented), positive definite Gaussians shaped by the input's regions.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <span>
#include <utility>

#include <Eigen/Eigenvalues>

#include "core/fitting/mesh_simplification.h"
#include "core/fitting/surface_distance.h"
#include "core/support/error.h"
#include "core/mesh/inference.h"
#include "core/modelling/samples.h"

namespace gps {
namespace {

struct Topology {
  long euler = 0;
  int boundary_loops = 0;
};

/// Euler characteristic and boundary loops counted from the face lists alone; fails the test where a
/// directed edge appears twice (a non-manifold edge or inconsistent orientation).
Topology topology_of(const CovarianceMesh& m) {
  std::set<std::pair<int, int>> directed;
  for (size_t f = 0; f < m.n_faces(); ++f) {
    const std::span<const int> corners = m.face(f);
    for (size_t k = 0; k < corners.size(); ++k) {
      const auto edge = std::make_pair(corners[k], corners[(k + 1) % corners.size()]);
      EXPECT_TRUE(directed.insert(edge).second) << "directed edge " << edge.first << "-" << edge.second << " twice";
    }
  }
  std::set<std::pair<int, int>> undirected;
  std::map<int, int> boundary_next;  // a boundary edge's end, from its start (reversed: the hole's direction)
  for (const auto& [a, b] : directed) {
    undirected.insert({std::min(a, b), std::max(a, b)});
    if (!directed.count({b, a})) {
      EXPECT_FALSE(boundary_next.count(b)) << "vertex " << b << " starts two boundary edges";
      boundary_next[b] = a;
    }
  }
  Topology t;
  t.euler = long(m.n_vertices()) - long(undirected.size()) + long(m.n_faces());
  std::set<int> seen;
  for (const auto& [start, next] : boundary_next) {
    if (seen.count(start)) continue;
    ++t.boundary_loops;
    for (int v = start; !seen.count(v); v = boundary_next.at(v)) seen.insert(v);
  }
  return t;
}

void expect_spd(const CovarianceMesh& m) {
  for (size_t i = 0; i < m.n_vertices(); ++i) EXPECT_TRUE(is_spd(m.covariance(i))) << "vertex " << i;
  EXPECT_EQ(gaussians_problem(m), "");
}

SimplifiedMesh simplified(const CovarianceMesh& m, size_t vertices) {
  SimplifyOptions options;
  options.target_vertices = vertices;
  return simplify_mesh(m, options);
}

TEST(Simplify, SphereKeepsGenusZeroAndOutwardFaces) {
  const CovarianceMesh input = make_sample("icosphere", 5120);
  ASSERT_EQ(topology_of(input).euler, 2);
  const SimplifiedMesh s = simplified(input, 200);
  EXPECT_FALSE(s.triangulated);
  EXPECT_EQ(s.input_vertices, input.n_vertices());
  EXPECT_EQ(s.mesh.n_vertices(), 200u);
  const Topology t = topology_of(s.mesh);
  EXPECT_EQ(t.euler, 2);
  EXPECT_EQ(t.boundary_loops, 0);
  expect_spd(s.mesh);
  // No flipped face: every triangle of the coarse sphere still faces away from its centre.
  for (size_t f = 0; f < s.mesh.n_faces(); ++f) {
    std::vector<Vec3> p;
    for (const int v : s.mesh.face(f)) p.push_back(s.mesh.mean(size_t(v)));
    const Vec3 normal = (p[1] - p[0]).cross(p[2] - p[0]);
    EXPECT_GT(normal.dot(p[0] + p[1] + p[2]), 0) << "face " << f;
  }
}

// Progress rises to the end and does not change the result; a report that asks to stop ends the
// simplification with Cancelled, early.
TEST(Simplify, ReportsProgressAndStopsWhenAsked) {
  const CovarianceMesh input = make_sample("icosphere", 5120);
  std::vector<double> seen;
  SimplifyOptions options;
  options.target_vertices = 200;
  options.progress = [&](double fraction) {
    seen.push_back(fraction);
    return true;
  };
  const SimplifiedMesh reported = simplify_mesh(input, options);
  ASSERT_GE(seen.size(), 50u);
  for (size_t i = 1; i < seen.size(); ++i) EXPECT_GT(seen[i], seen[i - 1]);
  EXPECT_GT(seen.front(), 0.0);
  EXPECT_LE(seen.back(), 1.0);
  EXPECT_GT(seen.back(), 0.95);
  EXPECT_EQ(reported.mesh.n_vertices(), 200u);
  const SimplifiedMesh plain = simplified(input, 200);
  for (size_t v = 0; v < plain.mesh.n_vertices(); ++v) {
    EXPECT_EQ(reported.mesh.mean(v), plain.mesh.mean(v));
    EXPECT_EQ(reported.mesh.covariance(v), plain.mesh.covariance(v));
  }

  int calls = 0;
  options.progress = [&](double fraction) {
    ++calls;
    return fraction < 0.3;
  };
  EXPECT_THROW(simplify_mesh(input, options), Cancelled);
  EXPECT_LT(calls, 40);
}

TEST(Simplify, TorusOfQuadsIsTriangulatedAndKeepsGenusOne) {
  const CovarianceMesh input = make_sample("torus");
  const SimplifiedMesh s = simplified(input, 60);
  EXPECT_TRUE(s.triangulated);
  EXPECT_EQ(s.input_triangles, 2 * input.n_faces());
  EXPECT_EQ(s.mesh.n_vertices(), 60u);
  const Topology t = topology_of(s.mesh);
  EXPECT_EQ(t.euler, 0);
  EXPECT_EQ(t.boundary_loops, 0);
  expect_spd(s.mesh);
}

TEST(Simplify, OpenGridKeepsItsOneBoundaryLoop) {
  const CovarianceMesh input = make_sample("grid", 1024);
  ASSERT_EQ(topology_of(input).boundary_loops, 1);
  const SimplifiedMesh s = simplified(input, 100);
  EXPECT_EQ(s.mesh.n_vertices(), 100u);
  const Topology t = topology_of(s.mesh);
  EXPECT_EQ(t.euler, 1);
  EXPECT_EQ(t.boundary_loops, 1);
  expect_spd(s.mesh);
  // The boundary keeps the grid's square outline over [−1, 1]²: its four corners, and no boundary
  // edge cuts across a corner (both ends of each on one side of the square).
  const auto on_side = [](const Vec3& p, int axis, double side) { return std::abs(p[axis] - side) < 1e-12; };
  int corners = 0;
  for (size_t i = 0; i < s.mesh.n_vertices(); ++i)
    corners += std::abs(std::abs(s.mesh.mean(i)[0]) - 1) < 1e-12 && std::abs(std::abs(s.mesh.mean(i)[1]) - 1) < 1e-12;
  EXPECT_EQ(corners, 4);
  for (size_t e = 0; e < s.mesh.n_edges(); ++e) {
    if (!s.mesh.is_boundary_edge(e)) continue;
    const Vec3 a = s.mesh.mean(size_t(s.mesh.edge(e)[0])), b = s.mesh.mean(size_t(s.mesh.edge(e)[1]));
    bool one_side = false;
    for (int axis = 0; axis < 2; ++axis)
      for (const double side : {-1.0, 1.0}) one_side = one_side || (on_side(a, axis, side) && on_side(b, axis, side));
    EXPECT_TRUE(one_side) << a.transpose() << " to " << b.transpose();
  }
}

TEST(Simplify, StopsWhereNoCollapseKeepsTheTopology) {
  // A tetrahedron has no collapse that keeps a closed genus-0 surface of triangles.
  const CovarianceMesh tetrahedron =
      make_covariance_mesh({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)},
                           std::vector<Mat3>(4, Mat3::Identity()), {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
  const SimplifiedMesh s = simplified(tetrahedron, 4);
  EXPECT_EQ(s.mesh.n_vertices(), 4u);
  EXPECT_EQ(topology_of(s.mesh).euler, 2);
  const CovarianceMesh octahedron = make_covariance_mesh(
      {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)},
      std::vector<Mat3>(6, Mat3::Identity()),
      {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}});
  const SimplifiedMesh o = simplified(octahedron, 4);
  EXPECT_GE(o.mesh.n_vertices(), 4u);
  EXPECT_EQ(topology_of(o.mesh).euler, 2);
  expect_spd(o.mesh);
}

TEST(Simplify, CommutesWithScale) {
  // Powers of two scale exactly, so the same collapses happen and Σ scales by s².
  const CovarianceMesh input = make_sample("pawn");
  const SimplifiedMesh reference = simplified(input, 120);
  for (const double scale : {std::ldexp(1.0, 40), std::ldexp(1.0, -40)}) {
    CovarianceMesh scaled = input;
    for (size_t i = 0; i < scaled.n_vertices(); ++i) scaled.set_mean(i, scale * input.mean(i));
    const SimplifiedMesh s = simplified(scaled, 120);
    ASSERT_EQ(s.mesh.n_vertices(), reference.mesh.n_vertices());
    ASSERT_EQ(s.mesh.n_faces(), reference.mesh.n_faces());
    for (size_t i = 0; i < s.mesh.n_vertices(); ++i) {
      EXPECT_EQ(s.mesh.mean(i), scale * reference.mesh.mean(i)) << "vertex " << i;
      EXPECT_LT((s.mesh.covariance(i) / (scale * scale) - reference.mesh.covariance(i)).norm(),
                1e-12 * reference.mesh.covariance(i).norm())
          << "vertex " << i;
    }
  }
}

TEST(Simplify, RefusesATargetBelowFour) { EXPECT_THROW(simplified(make_sample("icosphere", 320), 3), Error); }

// A pillow: a quad on top, two triangles under it split along the diagonal 0–2 that the quad's fan
// from its first corner would make an edge of four triangles: the quad is fanned from corner 1.
TEST(Simplify, APolygonIsFannedFromACornerWhoseDiagonalsAreNoEdges) {
  const CovarianceMesh pillow =
      make_covariance_mesh({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0.5), Vec3(0, 1, 0)},
                           std::vector<Mat3>(4, Mat3::Identity()), {{0, 1, 2, 3}, {0, 3, 2}, {0, 2, 1}});
  const SimplifiedMesh s = simplified(pillow, 4);
  EXPECT_TRUE(s.triangulated);
  EXPECT_EQ(s.mesh.n_faces(), 4u);
  EXPECT_GE(s.mesh.find_edge(1, 3), 0);
}

/// The box [−1, 1]³, each side an n × n grid of squares split into two triangles: a CAD-like mesh
/// whose sharp edges are where two sides meet.
CovarianceMesh finely_triangulated_box(int n) {
  std::vector<Vec3> points;
  std::map<std::tuple<long, long, long>, int> index;  // welds the sides along their shared edges
  const auto vertex = [&](const Vec3& p) {
    const auto key = std::make_tuple(std::lround(p[0] * n * 2), std::lround(p[1] * n * 2), std::lround(p[2] * n * 2));
    const auto [it, added] = index.emplace(key, int(points.size()));
    if (added) points.push_back(p);
    return it->second;
  };
  std::vector<std::vector<int>> faces;
  for (int axis = 0; axis < 3; ++axis)
    for (const double side : {-1.0, 1.0}) {
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      const auto at = [&](int i, int j) {
        Vec3 p;
        p[axis] = side;
        p[u] = -1 + 2.0 * i / n;
        p[w] = -1 + 2.0 * j / n;
        return vertex(p);
      };
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          // (u, w, axis) is right-handed: counter-clockwise seen from outside on the + side.
          std::vector<int> q{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
          if (side < 0) std::swap(q[1], q[3]);
          faces.push_back({q[0], q[1], q[2]});
          faces.push_back({q[0], q[2], q[3]});
        }
    }
  CovarianceMesh m = make_covariance_mesh(points, std::vector<Mat3>(points.size(), Mat3::Identity()), faces, "box");
  infer_covariances(m);
  return m;
}

TEST(Simplify, CreasesStayOnTheirChainsAndCornersStay) {
  // The box's 12 edges creased (dihedral 90°), a corner sharpness on one vertex of a side's middle.
  CovarianceMesh box = finely_triangulated_box(8);
  for (size_t e = 0; e < box.n_edges(); ++e) {
    const auto [v0, v1] = box.edge(e);
    const Vec3 a = box.mean(size_t(v0)), b = box.mean(size_t(v1));
    int shared_sides = 0;
    for (int k = 0; k < 3; ++k) shared_sides += std::abs(std::abs(a[k]) - 1) < 1e-12 && a[k] == b[k];
    if (shared_sides == 2) box.sharpness.set_crease(v0, v1, 10);
  }
  int pinned = -1;
  for (size_t i = 0; i < box.n_vertices(); ++i)
    if ((box.mean(i) - Vec3(0, 0, 1)).norm() < 1e-12) pinned = int(i);
  ASSERT_GE(pinned, 0);
  box.sharpness.set_corner(pinned, 3, int(box.n_vertices()));
  box.sharpness.normalise();
  ASSERT_EQ(box.sharpness.creases.size(), 12u * 8);

  const SimplifiedMesh s = simplified(box, 40);
  EXPECT_EQ(topology_of(s.mesh).euler, 2);
  const Sharpness& sharp = s.mesh.sharpness;
  ASSERT_FALSE(sharp.creases.empty());
  // Every crease edge runs along a box edge; they form 12 chains between the 8 corners: 3 creases
  // at a corner, 2 at every other vertex on them.
  std::map<int, int> creases_at;
  for (const EdgeCrease& c : sharp.creases) {
    EXPECT_EQ(c.sharpness, 10);
    const Vec3 a = s.mesh.mean(size_t(c.a)), b = s.mesh.mean(size_t(c.b));
    int shared_sides = 0;
    for (int k = 0; k < 3; ++k) shared_sides += std::abs(std::abs(a[k]) - 1) < 1e-12 && a[k] == b[k];
    EXPECT_EQ(shared_sides, 2) << a.transpose() << " to " << b.transpose();
    ++creases_at[c.a], ++creases_at[c.b];
  }
  int corners = 0;
  for (const auto& [v, n] : creases_at) {
    const Vec3 p = s.mesh.mean(size_t(v));
    const bool corner = (p.cwiseAbs() - Vec3::Ones()).norm() < 1e-12;
    corners += corner;
    EXPECT_EQ(n, corner ? 3 : 2) << "vertex " << v << " at " << p.transpose();
  }
  EXPECT_EQ(corners, 8);
  // The corner sharpness stays on the vertex at (0, 0, 1), which did not move.
  int kept = 0;
  for (size_t i = 0; i < s.mesh.n_vertices(); ++i)
    if (sharp.corner(int(i)) > 0) {
      ++kept;
      EXPECT_EQ(s.mesh.mean(i), Vec3(0, 0, 1));
      EXPECT_EQ(sharp.corner(int(i)), 3);
    }
  EXPECT_EQ(kept, 1);
}

TEST(Simplify, SharpEdgeVerticesGetNeedlesAlongTheEdge) {
  const CovarianceMesh box = finely_triangulated_box(16);
  ASSERT_EQ(topology_of(box).euler, 2);
  const SimplifiedMesh s = simplified(box, 150);
  EXPECT_EQ(s.mesh.n_vertices(), 150u);
  EXPECT_EQ(topology_of(s.mesh).euler, 2);
  expect_spd(s.mesh);
  int on_edges = 0;
  double ratios = 0;
  for (size_t i = 0; i < s.mesh.n_vertices(); ++i) {
    const Vec3 p = s.mesh.mean(i);
    int on_sides = 0, along = -1;
    for (int k = 0; k < 3; ++k) {
      if (std::abs(std::abs(p[k]) - 1) < 1e-12)
        ++on_sides;
      else
        along = k;
    }
    // A vertex on an edge, away from the corners whose regions reach round them.
    if (on_sides != 2 || std::abs(p[along]) > 0.6) continue;
    ++on_edges;
    const Eigen::SelfAdjointEigenSolver<Mat3> eigen(s.mesh.covariance(i));
    const Vec3 widest = eigen.eigenvectors().col(2);
    const double degrees = std::acos(std::min(1.0, std::abs(widest[along]))) * 180 / M_PI;
    EXPECT_LT(degrees, 2) << "vertex " << i << " at " << p.transpose();
    // σ along the edge over the next largest σ: √(1 + w/b) for the share w of its region's area on
    // the smaller side, 3.3 where both sides share alike at the default bias b = 0.05.
    const double ratio = std::sqrt(eigen.eigenvalues()(2) / eigen.eigenvalues()(1));
    EXPECT_GT(ratio, 1.5) << "vertex " << i << " at " << p.transpose();
    ratios += ratio;
  }
  ASSERT_GT(on_edges, 6);
  EXPECT_GT(ratios / on_edges, 2.5);
  // Those needles keep the limit surface nearer the box than plain isotropic Gaussians on the same
  // coarse mesh do.
  CovarianceMesh isotropic = s.mesh;
  isotropic_covariances(isotropic, 0.5);
  const std::vector<Vec3> points = vertex_means(box);
  const DistanceSummary region = distances_to_surface(points, limit_surface_triangles(s.mesh, 6).triangles);
  const DistanceSummary plain = distances_to_surface(points, limit_surface_triangles(isotropic, 6).triangles);
  EXPECT_LT(region.rms, plain.rms);
  EXPECT_LT(region.max, plain.max);
}

}  // namespace
}  // namespace gps
