// Creases and corners in the reference (core/reference/crease_rules.h): the rules' classification
// and decay, and properties of the creased surfaces that hold whatever OpenSubdiv does
// (test_crease_reference_osd.cpp compares with OpenSubdiv itself).
#include "core/reference/crease_rules.h"

#include <gtest/gtest.h>

#include "core/mesh/dual_map.h"
#include "core/reference/reference_subdivision.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

// The edge index of a–b in the mesh's connectivity (the reference's numbering of edge points).
int edge_of(const MeshConnectivity& c, int a, int b) {
  for (int e = 0; e < c.n_edges(); ++e)
    if (c.other_vertex(e, a) == b && (c.edge_verts[2 * size_t(e)] == a || c.edge_verts[2 * size_t(e) + 1] == a))
      return e;
  return -1;
}

void expect_same_gaussians(const SubdivisionResult& a, const SubdivisionResult& b) {
  ASSERT_EQ(a.mesh.n_vertices(), b.mesh.n_vertices());
  for (size_t i = 0; i < a.mesh.n_vertices(); ++i) {
    EXPECT_EQ(a.mesh.mean(i), b.mesh.mean(i)) << "vertex " << i;
    EXPECT_EQ(a.mesh.covariance(i), b.mesh.covariance(i)) << "vertex " << i;
  }
  ASSERT_EQ(a.normals.size(), b.normals.size());
  for (size_t i = 0; i < a.normals.size(); ++i) EXPECT_EQ(a.normals[i], b.normals[i]) << "vertex " << i;
}

double max_mean_distance(const CovarianceMesh& a, const std::vector<Vec3>& b) {
  double d = 0.0;
  for (size_t i = 0; i < b.size(); ++i) d = std::max(d, (a.mean(i) - b[i]).norm());
  return d;
}

CovarianceMesh sharp_top_cube(double sigma = 0.3) {
  CovarianceMesh m = test::cube_mesh(sigma);
  for (int k = 0; k < 4; ++k) m.sharpness.set_crease(4 + k, 4 + (k + 1) % 4, kInfiniteSharpness);
  return m;
}

TEST(CreaseRules, VertexRulesFollowSdc) {
  CovarianceMesh m = test::cube_mesh();
  m.sharpness.set_crease(0, 1, 2.5);
  m.sharpness.set_crease(1, 2, 1.0);
  m.sharpness.set_crease(1, 5, 0.5);
  m.sharpness.set_corner(6, 0.5, 8);
  const MeshConnectivity& c = m.connectivity();
  const CreaseLevel level = crease_level(m.sharpness, c, 8);
  int a = -1, b = -1;
  EXPECT_EQ(vertex_rule(c, level, 0), VertexRule::dart);
  EXPECT_EQ(vertex_rule(c, level, 1), VertexRule::corner);  // three sharp edges
  EXPECT_EQ(vertex_rule(c, level, 3), VertexRule::smooth);
  EXPECT_EQ(vertex_rule(c, level, 6), VertexRule::corner);  // a sharp vertex
  m.sharpness.set_crease(1, 5, 0.0);
  const CreaseLevel crease = crease_level(m.sharpness, c, 8);
  EXPECT_EQ(vertex_rule(c, crease, 1, &a, &b), VertexRule::crease);
  EXPECT_EQ(std::min(a, b), 0);
  EXPECT_EQ(std::max(a, b), 2);

  // Vertex 1 goes from crease (2.5 and 1) to dart (1.5): the sharpness 1 decays to smooth, weight 1.
  const VertexPointRule r = vertex_point_rule(c, crease, 1);
  EXPECT_EQ(r.parent, VertexRule::crease);
  EXPECT_EQ(r.child, VertexRule::dart);
  EXPECT_EQ(r.parent_weight, 1.0);

  // An open grid: boundary vertices are creases along the boundary, its corners corners.
  const CovarianceMesh grid = test::grid_mesh(3, 3);
  const MeshConnectivity& gc = grid.connectivity();
  EXPECT_EQ(vertex_rule(gc, CreaseLevel{}, 0), VertexRule::corner);
  EXPECT_EQ(vertex_rule(gc, CreaseLevel{}, 1, &a, &b), VertexRule::crease);
  EXPECT_EQ(std::min(a, b), 0);
  EXPECT_EQ(std::max(a, b), 2);
  EXPECT_EQ(vertex_rule(gc, CreaseLevel{}, 5), VertexRule::smooth);
}

TEST(CreaseRules, FractionalWeightIsTheMeanOfWhatDecays) {
  CovarianceMesh m = test::cube_mesh();
  m.sharpness.set_crease(0, 1, 0.25);
  m.sharpness.set_crease(0, 3, 0.75);
  m.sharpness.set_crease(0, 4, 3.0);
  const MeshConnectivity& c = m.connectivity();
  const VertexPointRule r = vertex_point_rule(c, crease_level(m.sharpness, c, 8), 0);
  EXPECT_EQ(r.parent, VertexRule::corner);
  EXPECT_EQ(r.child, VertexRule::dart);
  EXPECT_DOUBLE_EQ(r.parent_weight, 0.5);  // (0.25 + 0.75) / 2; the 3 stays sharp
  EXPECT_DOUBLE_EQ(edge_crease_weight(c, crease_level(m.sharpness, c, 8), edge_of(c, 0, 1)), 0.25);
}

TEST(CreaseRules, SharpnessDecaysOneLevelAtATime) {
  CovarianceMesh m = test::cube_mesh();
  m.sharpness.set_crease(0, 1, 2.5);
  m.sharpness.set_crease(4, 5, kInfiniteSharpness);
  m.sharpness.set_corner(7, 4.7, 8);
  const int e01 = edge_of(m.connectivity(), 0, 1);
  const SubdivisionResult one = subdivide(m, SubdivisionOptions{Scheme::catmull_clark, 1});
  EXPECT_EQ(one.mesh.sharpness.crease(0, 8 + e01), 1.5);
  EXPECT_EQ(one.mesh.sharpness.crease(1, 8 + e01), 1.5);
  EXPECT_EQ(one.mesh.sharpness.crease(0, 1), 0.0);
  EXPECT_EQ(one.mesh.sharpness.corner(7), decayed_sharpness(4.7));
  EXPECT_EQ(one.mesh.sharpness.creases.size(), 4u);  // two halves each of 0–1 and 4–5

  const SubdivisionResult three = subdivide(m, SubdivisionOptions{Scheme::catmull_clark, 3});
  EXPECT_EQ(three.mesh.sharpness.creases.size(), 8u);  // 0–1 has decayed; 4–5 in 8 pieces
  for (const EdgeCrease& crease : three.mesh.sharpness.creases) EXPECT_EQ(crease.sharpness, kInfiniteSharpness);
  EXPECT_NEAR(three.mesh.sharpness.corner(7), 1.7, 1e-12);
  EXPECT_EQ(three.mesh.sharpness.corners.size(), three.mesh.n_vertices());
}

TEST(CreaseRules, SharpnessOnBoundaryEdgesChangesNothing) {
  // A boundary edge is infinitely sharp already: marking it so must give the smooth result bit for bit.
  const struct {
    CovarianceMesh mesh;
    Scheme scheme;
  } cases[] = {{test::with_random_covariances(test::grid_mesh(4, 3), 21), Scheme::catmull_clark},
               {test::with_random_covariances(test::triangle_grid_mesh(4, 3), 22), Scheme::loop}};
  for (const auto& [mesh, scheme] : cases) {
    CovarianceMesh marked = mesh;
    const MeshConnectivity& c = mesh.connectivity();
    for (int e = 0; e < c.n_edges(); ++e)
      if (c.is_boundary_edge(e))
        marked.sharpness.set_crease(c.edge_verts[2 * size_t(e)], c.edge_verts[2 * size_t(e) + 1], kInfiniteSharpness);
    ASSERT_FALSE(marked.sharpness.empty());
    for (const bool limit : {false, true}) {
      SubdivisionOptions o{scheme, 3, limit};
      o.normals = limit;
      expect_same_gaussians(subdivide(marked, o), subdivide(mesh, o));
    }
  }
}

TEST(CreaseRules, EqualIsotropicCovariancesGiveThePlainCreasedScheme) {
  CovarianceMesh cube = test::cube_mesh();
  cube.sharpness.set_crease(0, 1, 0.5);
  cube.sharpness.set_crease(1, 2, 2.5);
  cube.sharpness.set_crease(4, 5, kInfiniteSharpness);
  cube.sharpness.set_corner(6, 1.5, 8);
  CovarianceMesh grid = test::grid_mesh(4, 3);
  for (int i = 0; i < 4; ++i) grid.sharpness.set_crease(5 + i, 6 + i, 1.7);
  CovarianceMesh ico = test::icosahedron_mesh();
  ico.sharpness.set_crease(0, 1, 0.5);
  ico.sharpness.set_crease(1, 5, 3.2);
  ico.sharpness.set_corner(3, kInfiniteSharpness, 12);
  const struct {
    const CovarianceMesh& mesh;
    Scheme scheme;
  } cases[] = {{cube, Scheme::catmull_clark}, {grid, Scheme::catmull_clark}, {ico, Scheme::loop}};
  for (const auto& [mesh, scheme] : cases) {
    CovarianceMesh smooth = mesh;
    smooth.sharpness = {};
    for (const bool limit : {false, true}) {
      const SubdivisionOptions o{scheme, 3, limit};
      const SubdivisionResult r = subdivide(mesh, o);
      EXPECT_LT(max_mean_distance(r.mesh, subdivide_points(mesh, o)), 1e-12 * bounding_box_diagonal(mesh));
      EXPECT_GT(max_mean_distance(r.mesh, subdivide_points(smooth, o)), 1e-3);  // the creases do something
    }
  }
}

TEST(CreaseRules, InfinitelySharpCreaseIsTheCubicBSplineOfItsVertices) {
  // The closed crease 4–5–6–7 (Catmull-Clark) or 2–3–4–5 (Loop): in the limit its vertices lie at
  // (a + 4v + b)/6 and the points of its edges at the segments' midpoints, (a + 23v + 23w + b)/48,
  // in 9D whatever the covariances (the B-spline of the 9D points), so for the means under equal
  // isotropic covariances.
  CovarianceMesh octahedron = test::bipyramid_mesh(4);
  for (int k = 0; k < 4; ++k) octahedron.sharpness.set_crease(2 + k, 2 + (k + 1) % 4, kInfiniteSharpness);
  const struct {
    CovarianceMesh mesh;
    Scheme scheme;
    int first;
  } cases[] = {{sharp_top_cube(), Scheme::catmull_clark, 4}, {octahedron, Scheme::loop, 2}};
  for (const auto& [base, scheme, first] : cases) {
    for (const bool equal : {true, false}) {
      const CovarianceMesh mesh = equal ? base : test::with_random_covariances(base, 23);
      const MeshConnectivity& c = mesh.connectivity();
      const int nv = int(mesh.n_vertices());
      const std::vector<Dual> q = base_points(mesh);
      const SubdivisionResult r = subdivide(mesh, SubdivisionOptions{scheme, 4, true});
      const auto ring = [&, first = first](int k) { return first + (k + 4) % 4; };
      for (int k = 0; k < 4; ++k) {
        const Dual at_vertex = (q[size_t(ring(k - 1))] + 4.0 * q[size_t(ring(k))] + q[size_t(ring(k + 1))]) / 6.0;
        const Dual at_midpoint = (q[size_t(ring(k - 1))] + 23.0 * q[size_t(ring(k))] + 23.0 * q[size_t(ring(k + 1))] +
                                  q[size_t(ring(k + 2))]) /
                                 48.0;
        const auto vertex = from_dual(at_vertex), midpoint = from_dual(at_midpoint);
        ASSERT_TRUE(vertex && midpoint);
        const size_t edge_point = size_t(nv + edge_of(c, ring(k), ring(k + 1)));
        EXPECT_LT((r.mesh.mean(size_t(ring(k))) - vertex->mean).norm(), 1e-12);
        EXPECT_LT((r.mesh.covariance(size_t(ring(k))) - vertex->covariance).norm(), 1e-12);
        EXPECT_LT((r.mesh.mean(edge_point) - midpoint->mean).norm(), 1e-12);
        EXPECT_LT((r.mesh.covariance(edge_point) - midpoint->covariance).norm(), 1e-12);
        if (equal) {
          const Vec3 p =
              (mesh.mean(size_t(ring(k - 1))) + 4.0 * mesh.mean(size_t(ring(k))) + mesh.mean(size_t(ring(k + 1)))) /
              6.0;
          EXPECT_LT((r.mesh.mean(size_t(ring(k))) - p).norm(), 1e-12);
        }
      }
    }
  }
}

TEST(CreaseRules, InfinitelySharpCornerStays) {
  for (const Scheme scheme : {Scheme::catmull_clark, Scheme::loop}) {
    CovarianceMesh mesh =
        test::with_random_covariances(scheme == Scheme::loop ? test::icosahedron_mesh() : test::cube_mesh(), 24);
    mesh.sharpness.set_corner(3, kInfiniteSharpness, int(mesh.n_vertices()));
    for (const bool limit : {false, true}) {
      const SubdivisionResult r = subdivide(mesh, SubdivisionOptions{scheme, 3, limit});
      EXPECT_LT((r.mesh.mean(3) - mesh.mean(3)).norm(), 1e-12);
      EXPECT_LT((r.mesh.covariance(3) - mesh.covariance(3)).norm(), 1e-12);
      EXPECT_GT((r.mesh.mean(2) - mesh.mean(2)).norm(), 1e-3);  // its neighbours move
    }
  }
}

// Where all sharpness is infinite the rules are the same at every level, so each vertex's limit is the
// same whichever level projects it: at darts too, whose ring steps with the sharp edge's midpoint
// (the smooth mask, which Far takes there, moves with the level).
TEST(CreaseRules, LimitPositionsAtDartsAreFixedUnderFurtherSubdivision) {
  CovarianceMesh cube = test::with_random_covariances(test::cube_mesh(), 25);
  cube.sharpness.set_crease(4, 5, kInfiniteSharpness);  // darts of valence 3 at 4 and 5
  cube.sharpness.set_crease(2, 6, kInfiniteSharpness);
  cube.sharpness.set_crease(6, 7, kInfiniteSharpness);  // a crease vertex at 6, darts at 2 and 7
  CovarianceMesh icosahedron = test::with_random_covariances(test::icosahedron_mesh(), 26);
  icosahedron.sharpness.set_crease(7, 10, kInfiniteSharpness);  // darts of valence 5
  CovarianceMesh grid = test::with_random_covariances(test::triangle_grid_mesh(4, 4), 27);
  grid.sharpness.set_crease(2 * 5 + 1, 2 * 5 + 2, kInfiniteSharpness);  // darts of valence 6
  const struct {
    const CovarianceMesh& mesh;
    Scheme scheme;
  } cases[] = {{cube, Scheme::catmull_clark}, {icosahedron, Scheme::loop}, {grid, Scheme::loop}};
  for (const auto& [mesh, scheme] : cases) {
    const SubdivisionResult coarse = subdivide(mesh, SubdivisionOptions{scheme, 1, true});
    const SubdivisionResult fine = subdivide(mesh, SubdivisionOptions{scheme, 4, true});
    const double diagonal = bounding_box_diagonal(mesh);
    for (size_t i = 0; i < coarse.mesh.n_vertices(); ++i)
      EXPECT_LT((coarse.mesh.mean(i) - fine.mesh.mean(i)).norm(), 1e-12 * diagonal) << "vertex " << i;
  }
}

TEST(CreaseRules, CreaseAndCornerVerticesHaveNoLimitNormal) {
  CovarianceMesh mesh = sharp_top_cube();
  mesh.sharpness.set_corner(0, kInfiniteSharpness, 8);
  SubdivisionOptions o{Scheme::catmull_clark, 2, true};
  o.normals = true;
  const SubdivisionResult r = subdivide(mesh, o);
  for (const int v : {0, 4, 5, 6, 7}) EXPECT_EQ(r.normals[size_t(v)], Vec3::Zero()) << "vertex " << v;
  for (const int v : {1, 2, 3}) EXPECT_NEAR(r.normals[size_t(v)].norm(), 1.0, 1e-12) << "vertex " << v;
}

}  // namespace
}  // namespace gps
