// Loop cuts: the ring of edges a cut crosses (closed around the cube and the cylinder, open at a
// boundary or a face that is not a quad), the cut's counts, faces, orientation and new Gaussians, and
// on a grid of equal isotropic Gaussians the cut mesh's GPS limit is plain Catmull-Clark's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>

#include "core/modelling/samples.h"
#include "core/modelling/loop_cut.h"
#include "core/reference/reference_subdivision.h"
#include "tests/support/error_of.h"
#include "tests/support/test_meshes.h"
#include "tests/support/mesh_checks.h"

namespace gps {
namespace {

using test::expect_same_arrays;

using test::error_of;
using Edge = std::array<int, 2>;

// Checks that every directed edge lies in one face at most (manifold, consistently oriented);
// returns the number of boundary edges.
int checked_boundary_edges(const CovarianceMesh& m) {
  const MeshArrays a = arrays_of(m);
  std::map<std::pair<int, int>, int> directed;
  for (const auto& f : a.faces)
    for (size_t k = 0; k < f.size(); ++k) ++directed[{f[k], f[(k + 1) % f.size()]}];
  int boundary = 0;
  for (const auto& [e, n] : directed) {
    EXPECT_EQ(n, 1) << "directed edge " << e.first << "→" << e.second;
    if (!directed.count({e.second, e.first})) ++boundary;
  }
  return boundary;
}

// Consecutive ring edges joined end to end on each side (first ends to first ends).
void expect_consistent(const CovarianceMesh& m, const EdgeRing& ring) {
  const DirectedEdges edges = directed_edges(arrays_of(m));
  const size_t n = ring.edges.size(), links = ring.closed ? n : n - 1;
  for (size_t i = 0; i < links; ++i) {
    const Edge p = ring.edges[i], q = ring.edges[(i + 1) % n];
    EXPECT_TRUE(has_edge(edges, p[0], q[0]) && has_edge(edges, p[1], q[1])) << "ring edges " << i << ", " << i + 1;
  }
}

std::vector<Vec3> limit_means(const CovarianceMesh& m, int levels) {
  SubdivisionOptions o;
  o.levels = levels;
  o.limit = true;
  const SubdivisionResult r = subdivide(m, o);
  std::vector<Vec3> p;
  for (size_t v = 0; v < r.mesh.n_vertices(); ++v) p.push_back(r.mesh.mean(v));
  return p;
}

TEST(EdgeRing, ClosedAroundTheCube) {
  const CovarianceMesh m = make_sample("cube");
  const EdgeRing ring = edge_ring(m, 0, 1);
  EXPECT_TRUE(ring.closed);
  ASSERT_EQ(ring.edges.size(), 4u);
  EXPECT_EQ(ring.edges[0], (Edge{0, 1}));
  expect_consistent(m, ring);
  const EdgeRing reversed = edge_ring(m, 1, 0);
  EXPECT_EQ(reversed.edges[0], (Edge{1, 0}));
  expect_consistent(m, reversed);
}

TEST(EdgeRing, AroundTheCylinderAndBetweenItsCaps) {
  const CovarianceMesh m = make_sample("cylinder");
  const EdgeRing axial = edge_ring(m, 0, 8);  // crosses the quads around the cylinder
  EXPECT_TRUE(axial.closed);
  EXPECT_EQ(axial.edges.size(), 8u);
  expect_consistent(m, axial);
  const EdgeRing ring = edge_ring(m, 8, 9);  // from cap to cap, stopped by the octagons
  EXPECT_FALSE(ring.closed);
  EXPECT_EQ(ring.edges, (std::vector<Edge>{{0, 1}, {8, 9}, {16, 17}}));
}

TEST(EdgeRing, OpenAtTheBoundaryOfAGrid) {
  const CovarianceMesh m = make_sample("grid", 16);  // 4 × 4 quads
  const EdgeRing ring = edge_ring(m, 0, 1);
  EXPECT_FALSE(ring.closed);
  ASSERT_EQ(ring.edges.size(), 5u);
  EXPECT_EQ(ring.edges.front(), (Edge{0, 1}));
  EXPECT_EQ(ring.edges.back(), (Edge{20, 21}));
  expect_consistent(m, ring);
  EXPECT_EQ(error_of([&] { edge_ring(m, 0, 6); }), "edge 0–6 is not in the mesh");
  EXPECT_EQ(error_of([&] { edge_ring(m, 0, 25); }), "vertex 25 is not in the mesh (25 vertices)");
}

TEST(LoopCut, OneAndTwoLoopsAroundTheCube) {
  const CovarianceMesh m = test::with_random_covariances(make_sample("cube"), 4);
  const MeshArrays before = arrays_of(m);
  const EdgeRing ring = edge_ring(m, 0, 1);
  for (int cuts : {1, 2, 3}) {
    const Modelled r = loop_cut(m, 0, 1, cuts);
    const MeshArrays a = arrays_of(r.mesh);
    ASSERT_EQ(a.n_vertices(), 8 + 4 * cuts);
    ASSERT_EQ(a.n_faces(), 6 + 4 * cuts);
    EXPECT_EQ(checked_boundary_edges(r.mesh), 0);
    for (const auto& f : a.faces) EXPECT_EQ(f.size(), 4u);
    std::vector<int> added;
    for (int v = 8; v < a.n_vertices(); ++v) added.push_back(v);
    EXPECT_EQ(r.selection, added);
    // Ring edge by ring edge, each from its first end, at k / (cuts + 1).
    int v = 8;
    for (const Edge& e : ring.edges)
      for (int k = 1; k <= cuts; ++k, ++v) {
        const double t = double(k) / (cuts + 1);
        const Gaussian want = blend_gaussians(before, {{e[0], 1 - t}, {e[1], t}});
        EXPECT_LE((a.means[size_t(v)] - want.mean).norm(), 1e-14);
        EXPECT_LE((a.covariances[size_t(v)] - want.covariance).norm(), 1e-14 * want.covariance.norm());
      }
  }
  EXPECT_EQ(loop_cut(m, 0, 1).summary, "cut 1 loop across 4 quads: 4 vertices, 4 faces added");
  // The ring's quads keep their index for the piece on vertex 0's side.
  const MeshArrays one = arrays_of(loop_cut(m, 0, 1).mesh);
  for (int f : {0, 1, 2, 3}) {
    const auto& c = one.faces[size_t(f)];
    const int on_a_side =
        int(std::count_if(c.begin(), c.end(), [](int v) { return v == 0 || v == 3 || v == 4 || v == 7; }));
    EXPECT_EQ(on_a_side, 2) << "face " << f;
  }
  expect_same_arrays(arrays_of(m), before);
}

TEST(LoopCut, SlideMovesTheCutsTowardsAnEnd) {
  const CovarianceMesh m = make_sample("cube");
  const auto fraction_on_0_1 = [&](int cuts, double slide, int k) {
    const Modelled r = loop_cut(m, 0, 1, cuts, slide);
    return (r.mesh.mean(size_t(8 + k)) - m.mean(0)).norm() / (m.mean(1) - m.mean(0)).norm();
  };
  EXPECT_NEAR(fraction_on_0_1(1, 0.5, 0), 0.75, 1e-14);
  EXPECT_NEAR(fraction_on_0_1(1, -0.5, 0), 0.25, 1e-14);
  EXPECT_NEAR(fraction_on_0_1(3, 0.5, 0), 0.625, 1e-14);
  EXPECT_NEAR(fraction_on_0_1(3, 0.5, 2), 0.875, 1e-14);
  EXPECT_NEAR(fraction_on_0_1(3, -0.5, 2), 0.375, 1e-14);
}

TEST(LoopCut, EndFacesThatAreNotQuadsTakeTheNewVertices) {
  const CovarianceMesh m = make_sample("cylinder");
  const Modelled r = loop_cut(m, 8, 9, 2);
  const MeshArrays a = arrays_of(r.mesh);
  EXPECT_EQ(a.n_vertices(), 24 + 3 * 2);
  EXPECT_EQ(a.n_faces(), 18 + 2 * 2);
  EXPECT_EQ(checked_boundary_edges(r.mesh), 0);
  EXPECT_EQ(a.faces[16].size(), 10u);  // the top octagon and the two new vertices on 16–17
  EXPECT_EQ(a.faces[17].size(), 10u);
  const Modelled around = loop_cut(m, 0, 8);
  EXPECT_EQ(around.mesh.n_vertices(), 24u + 8u);
  EXPECT_EQ(around.mesh.n_faces(), 18u + 8u);
  EXPECT_EQ(checked_boundary_edges(around.mesh), 0);
}

TEST(LoopCut, OpenRingOnAGridAndLinearMeansForEqualIsotropicGaussians) {
  const CovarianceMesh m = test::grid_mesh(4, 4);
  const Modelled r = loop_cut(m, 0, 1, 1, 0.2);
  const MeshArrays a = arrays_of(r.mesh);
  EXPECT_EQ(a.n_vertices(), 25 + 5);
  EXPECT_EQ(a.n_faces(), 16 + 4);
  EXPECT_EQ(checked_boundary_edges(r.mesh), checked_boundary_edges(m) + 2);
  const double t = 0.5 + 0.2 * 0.5;
  const EdgeRing ring = edge_ring(m, 0, 1);
  for (size_t i = 0; i < ring.edges.size(); ++i) {
    const Vec3 want = (1 - t) * m.mean(size_t(ring.edges[i][0])) + t * m.mean(size_t(ring.edges[i][1]));
    EXPECT_LE((a.means[25 + i] - want).norm(), 4e-16 * (1 + want.norm()));
    EXPECT_LE((a.covariances[25 + i] - m.covariance(0)).norm(), 4e-16 * m.covariance(0).norm());
  }
}

// With equal isotropic Gaussians GPS is the linear scheme on the means: the cut mesh's limit equals
// plain Catmull-Clark's. The cut itself moves the limit surface (the new knot line makes the spacing
// uneven, which uniform Catmull-Clark does not reproduce): measured at the old vertices' limits.
TEST(LoopCut, ActsAsPlainCatmullClarkOnEqualIsotropicGaussians) {
  const CovarianceMesh m = test::grid_mesh(6, 5);
  const Modelled r = loop_cut(m, 9, 10);  // an interior edge: the ring runs across the grid
  SubdivisionOptions o;
  o.levels = 2;
  o.limit = true;
  const std::vector<Vec3> linear = subdivide_points(r.mesh, o);
  const std::vector<Vec3> gps = limit_means(r.mesh, 2);
  ASSERT_EQ(gps.size(), linear.size());
  const double diagonal = bounding_box_diagonal(m);
  double worst = 0;
  for (size_t v = 0; v < gps.size(); ++v) worst = std::max(worst, (gps[v] - linear[v]).norm());
  EXPECT_LE(worst, 1e-12 * diagonal);

  const std::vector<Vec3> uncut = limit_means(m, 0), cut = limit_means(r.mesh, 0);
  double moved = 0;
  for (size_t v = 0; v < m.n_vertices(); ++v) moved = std::max(moved, (cut[v] - uncut[v]).norm());
  moved /= diagonal;
  std::cout << "loop cut: the old vertices' limits move by " << moved << " of the bounding-box diagonal\n";
  RecordProperty("limit_displacement_relative_to_diagonal", std::to_string(moved));
  EXPECT_GT(moved, 1e-6);  // not surface-preserving
  EXPECT_LT(moved, 0.02);  // but a small change near the cut
}

TEST(LoopCut, RefusalsNameTheProblemAndChangeNothing) {
  const CovarianceMesh m = make_sample("cube");
  const MeshArrays before = arrays_of(m);
  EXPECT_EQ(error_of([&] { loop_cut(m, 0, 6); }), "edge 0–6 is not in the mesh");
  EXPECT_EQ(error_of([&] { loop_cut(m, 0, 8); }), "vertex 8 is not in the mesh (8 vertices)");
  EXPECT_EQ(error_of([&] { loop_cut(m, 0, 1, 0); }), "the number of cuts must be 1..64, got 0");
  EXPECT_EQ(error_of([&] { loop_cut(m, 0, 1, 65); }), "the number of cuts must be 1..64, got 65");
  EXPECT_EQ(error_of([&] { loop_cut(m, 0, 1, 1, 1.0); }), "the slide must be in (−1, 1), got 1");
  EXPECT_EQ(error_of([&] { loop_cut(m, 0, 1, 1, -1.5); }), "the slide must be in (−1, 1), got -1.5");
  EXPECT_EQ(error_of([&] { loop_cut(m, 0, 1, 1, std::numeric_limits<double>::quiet_NaN()); }),
            "the slide must be in (−1, 1), got nan");
  EXPECT_EQ(loop_cut(m, 0, 1, 64).mesh.n_vertices(), 8u + 4u * 64u);
  expect_same_arrays(arrays_of(m), before);
  const CovarianceMesh ico = test::icosahedron_mesh();
  EXPECT_EQ(error_of([&] { loop_cut(ico, 0, 11); }), "edge 0–11 has no quad beside it to cut across");
}

}  // namespace
}  // namespace gps
