#include "core/modelling/bevel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <random>

#include "core/modelling/delete_elements.h"
#include "core/modelling/extrude.h"
#include "core/modelling/mesh_queries.h"
#include "core/modelling/samples.h"
#include "core/modelling/operation_list.h"
#include "tests/support/error_of.h"
#include "tests/support/test_meshes.h"
#include "tests/support/mesh_checks.h"
#include "tests/support/bevel_width.h"

namespace gps {
namespace {

using test::signed_volume;

using test::error_of;
using test::grid_mesh;
using test::icosahedron_mesh;
using test::with_random_covariances;

/// Whether every directed edge of the faces appears once and has its reverse (closed, manifold and
/// consistently oriented).
bool closed_and_oriented(const CovarianceMesh& mesh) {
  const MeshArrays a = arrays_of(mesh);
  std::map<std::pair<int, int>, int> directed;
  for (const auto& face : a.faces)
    for (size_t k = 0; k < face.size(); ++k) ++directed[{face[k], face[(k + 1) % face.size()]}];
  for (const auto& [e, n] : directed)
    if (n != 1 || !directed.count({e.second, e.first})) return false;
  return true;
}

bool all_triangles(const CovarianceMesh& mesh) {
  for (const auto& face : arrays_of(mesh).faces)
    if (face.size() != 3) return false;
  return true;
}

/// The vertex of the mesh at `p` (−1 if none).
int vertex_at(const CovarianceMesh& mesh, const Vec3& p) {
  for (size_t v = 0; v < mesh.n_vertices(); ++v)
    if ((mesh.mean(v) - p).norm() < 1e-12) return int(v);
  return -1;
}

using test::width;

// The cube sample: corners 0..7 at (±1, ±1, ±1), vertex 4 at (−1, −1, 1), 5 at (1, −1, 1), 7 at
// (−1, 1, 1), 0 at (−1, −1, −1); edge 4–5 lies on the top (+z) and front (−y) faces.
TEST(BevelEdges, OneCubeEdgeWithOneSegmentGivesTenVerticesAndSevenFaces) {
  const CovarianceMesh cube = make_sample("cube");
  const Modelled m = bevel_edges(cube, {{4, 5}}, width(0.25));
  EXPECT_EQ(m.mesh.n_vertices(), 10u);
  EXPECT_EQ(m.mesh.n_faces(), 7u);
  EXPECT_TRUE(closed_and_oriented(m.mesh));
  // The cut-off prism: a right triangle of legs 0.25 along the edge's length 2.
  EXPECT_NEAR(signed_volume(m.mesh), 8 - 0.25 * 0.25 / 2 * 2, 1e-12);
  EXPECT_EQ(m.selection, (std::vector<int>{6, 7, 8, 9}));
  for (const Vec3& p : {Vec3(-1, -0.75, 1), Vec3(-1, -1, 0.75), Vec3(1, -0.75, 1), Vec3(1, -1, 0.75)})
    EXPECT_GE(vertex_at(m.mesh, p), 6) << p.transpose();
  EXPECT_EQ(m.summary, "bevelled 1 edge: 4 vertices in place of 2, 1 face added");
}

TEST(BevelEdges, OneCubeEdgeWithTwoSegmentsGivesTwelveVerticesAndEightFacesOnACircle) {
  const CovarianceMesh cube = make_sample("cube");
  const Modelled m = bevel_edges(cube, {{4, 5}}, width(0.25, 2));
  EXPECT_EQ(m.mesh.n_vertices(), 12u);
  EXPECT_EQ(m.mesh.n_faces(), 8u);
  EXPECT_TRUE(closed_and_oriented(m.mesh));
  // Profile 0.5: the middle vertex on the quarter circle of radius 0.25 about (x, −0.75, 0.75), so
  // each end face loses the quadrilateral corner, the edge, the two ends and the middle.
  EXPECT_NEAR(signed_volume(m.mesh), 8 - 2 * 0.0625 * (1 - 1 / std::sqrt(2.0)), 1e-12);
  const double inward = 0.25 * (1 - 1 / std::sqrt(2.0));
  EXPECT_GE(vertex_at(m.mesh, Vec3(-1, -1 + inward, 1 - inward)), 8);
  EXPECT_GE(vertex_at(m.mesh, Vec3(1, -1 + inward, 1 - inward)), 8);
}

TEST(BevelVertices, OneCubeVertexGivesTenVerticesAndSevenFaces) {
  const CovarianceMesh cube = make_sample("cube");
  const Modelled m = bevel_vertices(cube, {4}, width(0.5));
  EXPECT_EQ(m.mesh.n_vertices(), 10u);
  EXPECT_EQ(m.mesh.n_faces(), 7u);
  EXPECT_TRUE(closed_and_oriented(m.mesh));
  EXPECT_NEAR(signed_volume(m.mesh), 8 - 0.5 * 0.5 * 0.5 / 6, 1e-12);
  for (const Vec3& p : {Vec3(-0.5, -1, 1), Vec3(-1, -0.5, 1), Vec3(-1, -1, 0.5)}) EXPECT_GE(vertex_at(m.mesh, p), 7);
  EXPECT_EQ(m.summary, "bevelled 1 vertex: 3 vertices in place of 1, 1 face added");
}

TEST(BevelVertices, SegmentsRoundEachFaceCorner) {
  const CovarianceMesh cube = make_sample("cube");
  const Modelled m = bevel_vertices(cube, {4}, width(0.5, 3));
  // Three new vertices on the edges and two inside each of the three faces' profiles.
  EXPECT_EQ(m.mesh.n_vertices(), 7u + 3 + 3 * 2);
  EXPECT_EQ(m.mesh.n_faces(), 7u);
  EXPECT_TRUE(closed_and_oriented(m.mesh));
  EXPECT_GT(signed_volume(m.mesh), 8 - 0.5 * 0.5 * 0.5 / 6);
  EXPECT_LT(signed_volume(m.mesh), 8);
  // The profile in the top face: a quarter circle of radius 0.5 about (−0.5, −0.5, 1) at 30° steps.
  const Vec3 centre(-0.5, -0.5, 1);
  EXPECT_GE(vertex_at(m.mesh, centre - 0.5 * Vec3(std::cos(M_PI / 6), std::sin(M_PI / 6), 0)), 7);
  EXPECT_GE(vertex_at(m.mesh, centre - 0.5 * Vec3(std::sin(M_PI / 6), std::cos(M_PI / 6), 0)), 7);
}

TEST(BevelEdges, NewVerticesGetTheNineDimensionalBlends) {
  const CovarianceMesh cube = with_random_covariances(make_sample("cube"), 7);
  const MeshArrays before = arrays_of(cube);
  const double w = 0.25;
  const Modelled m = bevel_edges(cube, {{4, 5}}, width(w, 2));
  // A vertex moved along an edge v→u by the fraction t (the edges are 2 long): (1 − t) q_v + t q_u.
  const std::vector<std::array<int, 2>> slides = {{4, 0}, {4, 7}, {5, 1}, {5, 6}};
  for (const auto& [v, u] : slides) {
    const int moved =
        vertex_at(m.mesh, before.means[size_t(v)] + w / 2 * (before.means[size_t(u)] - before.means[size_t(v)]));
    ASSERT_GE(moved, 0);
    EXPECT_TRUE(m.mesh.covariances[size_t(moved)].isApprox(
        blend_gaussians(before, {{v, 1 - w / 2}, {u, w / 2}}).covariance, 1e-12));
  }
  // A profile's middle vertex: the even blend of the profile's ends.
  const MeshArrays after = arrays_of(m.mesh);
  const double inward = 0.25 * (1 - 1 / std::sqrt(2.0));
  const int middle = vertex_at(m.mesh, Vec3(-1, -1 + inward, 1 - inward));
  const int top = vertex_at(m.mesh, Vec3(-1, -0.75, 1)), side = vertex_at(m.mesh, Vec3(-1, -1, 0.75));
  ASSERT_GE(middle, 0);
  EXPECT_TRUE(
      m.mesh.covariances[size_t(middle)].isApprox(blend_gaussians(after, {{top, 0.5}, {side, 0.5}}).covariance, 1e-12));
}

TEST(BevelEdges, ThreeEdgesAtACornerMeetInsideTheFacesWithTheirBarycentricBlends) {
  const CovarianceMesh cube = with_random_covariances(make_sample("cube"), 3);
  const MeshArrays before = arrays_of(cube);
  const double w = 0.5;
  const Modelled m = bevel_edges(cube, {{4, 5}, {4, 7}, {0, 4}}, width(w));
  // Vertex 4 becomes a triangle of three vertices in its faces; 5, 7 and 0 two each on their edges.
  EXPECT_EQ(m.mesh.n_vertices(), 8u - 4 + 3 + 6);
  EXPECT_EQ(m.mesh.n_faces(), 6u + 3 + 1);
  EXPECT_TRUE(closed_and_oriented(m.mesh));
  EXPECT_GT(signed_volume(m.mesh), 0);
  // In the top face, at offset w from edges 4–5 and 4–7: (−1 + w, −1 + w, 1), the corner's triangle
  // weights (1 − w, w/2, w/2) over 4, 5 and 7 (edges of length 2).
  const int in_top = vertex_at(m.mesh, Vec3(-1 + w, -1 + w, 1));
  ASSERT_GE(in_top, 0);
  EXPECT_TRUE(m.mesh.covariances[size_t(in_top)].isApprox(
      blend_gaussians(before, {{4, 1 - w}, {5, w / 2}, {7, w / 2}}).covariance, 1e-12));
}

TEST(BevelEdges, RimsAreCreasedWhenAskedAndOtherCreasesFollowTheirEdges) {
  CovarianceMesh cube = make_sample("cube");
  cube.sharpness.set_crease(4, 7, 3.0);
  BevelOptions o = width(0.25);
  o.crease = 2.0;
  const Modelled m = bevel_edges(cube, {{4, 5}}, o);
  const int top4 = vertex_at(m.mesh, Vec3(-1, -0.75, 1)), top5 = vertex_at(m.mesh, Vec3(1, -0.75, 1));
  const int side4 = vertex_at(m.mesh, Vec3(-1, -1, 0.75)), side5 = vertex_at(m.mesh, Vec3(1, -1, 0.75));
  const int seven = vertex_at(m.mesh, Vec3(-1, 1, 1));
  EXPECT_EQ(m.mesh.sharpness.crease(top4, top5), 2.0);
  EXPECT_EQ(m.mesh.sharpness.crease(side4, side5), 2.0);
  // Edge 4–7 is now from the new vertex on it to 7, and keeps its sharpness.
  EXPECT_EQ(m.mesh.sharpness.crease(top4, seven), 3.0);
  EXPECT_EQ(m.mesh.sharpness.creases.size(), 3u);

  const Modelled plain = bevel_edges(make_sample("cube"), {{4, 5}}, width(0.25));
  EXPECT_TRUE(plain.mesh.sharpness.creases.empty());
}

TEST(BevelEdges, ABevelledCreaseGoesWithItsEdge) {
  CovarianceMesh cube = make_sample("cube");
  cube.sharpness.set_crease(4, 5, 3.0);
  EXPECT_TRUE(bevel_edges(cube, {{4, 5}}, width(0.25)).mesh.sharpness.creases.empty());
}

TEST(BevelEdges, ThreeSegmentsOnAQuadMesh) {
  const CovarianceMesh cube = make_sample("cube");
  // The four edges of the top face: two bevelled edges at each top corner share one profile.
  const Modelled m = bevel_edges(cube, {{4, 5}, {5, 6}, {6, 7}, {7, 4}}, width(0.25, 3));
  EXPECT_EQ(m.mesh.n_vertices(), 8u - 4 + 4 * (2 + 2));
  EXPECT_EQ(m.mesh.n_faces(), 6u + 4 * 3);
  EXPECT_TRUE(closed_and_oriented(m.mesh));
  EXPECT_GT(signed_volume(m.mesh), 8 - 4 * 2 * 0.0625 / 2 - 1e-9);
  EXPECT_LT(signed_volume(m.mesh), 8);
}

TEST(BevelEdges, ThreeSegmentsOnATriangleMeshStayTriangles) {
  const CovarianceMesh ico = icosahedron_mesh();
  const double volume = signed_volume(ico);
  const Modelled m = bevel_edges(ico, {{0, 5}}, width(0.1, 3));
  EXPECT_TRUE(all_triangles(m.mesh));
  EXPECT_TRUE(closed_and_oriented(m.mesh));
  // At each end (valence 5), as Blender's: a vertex on each of its four other edges and two inside
  // its profile, the end itself gone. As triangles: the 12 faces away from the edge, its 2 faces, the
  // 3 faces at each end around the edges across (each widened into 2), the band's 3 quads (6) and
  // each end's hexagon (4).
  EXPECT_EQ(m.mesh.n_vertices(), 12u - 2 + 2 * 6);
  EXPECT_EQ(m.mesh.n_faces(), 12u + 2 + 2 * 6 + 6 + 2 * 4);
  EXPECT_GT(signed_volume(m.mesh), 0.95 * volume);
  EXPECT_LT(signed_volume(m.mesh), volume);

  const CovarianceMesh sphere = make_sample("icosphere", 80);
  const std::vector<int> face = arrays_of(sphere).faces[0];
  const Modelled s = bevel_edges(sphere, {{face[0], face[1]}}, width(0.05, 3));
  EXPECT_TRUE(all_triangles(s.mesh));
  EXPECT_TRUE(closed_and_oriented(s.mesh));
  EXPECT_GT(signed_volume(s.mesh), 0);
}

TEST(BevelVertices, ThreeSegmentsOnATriangleMeshStayTriangles) {
  const CovarianceMesh ico = icosahedron_mesh();
  const Modelled m = bevel_vertices(ico, {0}, width(0.2, 3));
  EXPECT_TRUE(all_triangles(m.mesh));
  EXPECT_TRUE(closed_and_oriented(m.mesh));
  EXPECT_EQ(m.mesh.n_vertices(), 12u - 1 + 5 + 5 * 2);
  EXPECT_EQ(m.mesh.n_faces(), 20u + 5 * 3 + 13);
  EXPECT_GT(signed_volume(m.mesh), 0);
  EXPECT_LT(signed_volume(m.mesh), signed_volume(ico));
}

TEST(BevelEdges, EveryEdgeOfACube) {
  const CovarianceMesh cube = make_sample("cube");
  std::vector<std::array<int, 2>> all;
  for (const auto& face : arrays_of(cube).faces)
    for (size_t k = 0; k < 4; ++k)
      if (face[k] < face[(k + 1) % 4]) all.push_back({face[k], face[(k + 1) % 4]});
  ASSERT_EQ(all.size(), 12u);
  // Each corner becomes a triangle of vertices in its faces: 24 vertices; 6 faces, 12 bands, 8 corners.
  const Modelled m = bevel_edges(cube, all, width(0.2));
  EXPECT_EQ(m.mesh.n_vertices(), 24u);
  EXPECT_EQ(m.mesh.n_faces(), 26u);
  EXPECT_TRUE(closed_and_oriented(m.mesh));
  // Each band's prism (legs 0.2, length 2 − 0.4) and each corner's tetrahedron-like cap are cut off.
  EXPECT_LT(signed_volume(m.mesh), 8 - 12 * 0.02 * 1.6);
  EXPECT_GT(signed_volume(m.mesh), 8 - 12 * 0.02 * 2);
}

TEST(BevelEdges, AnySetOfEdgesOnClosedMeshesGivesAClosedOrientedMeshOrARefusal) {
  std::mt19937 rng(11);
  for (const char* name : {"sphere", "icosphere", "torus", "cylinder"}) {
    const CovarianceMesh mesh = make_sample(name, 100);
    const MeshArrays a = arrays_of(mesh);
    std::vector<std::array<int, 2>> edges;
    for (const auto& face : a.faces)
      for (size_t k = 0; k < face.size(); ++k)
        if (face[k] < face[(k + 1) % face.size()]) edges.push_back({face[k], face[(k + 1) % face.size()]});
    const bool triangles = all_triangles(mesh);
    for (int trial = 0; trial < 40; ++trial) {
      std::vector<std::array<int, 2>> chosen;
      const size_t count = 1 + rng() % 6;
      for (size_t i = 0; i < count; ++i) chosen.push_back(edges[rng() % edges.size()]);
      const int segments = 1 + int(rng() % 3);
      try {
        const Modelled m = bevel_edges(mesh, chosen, width(0.02, segments));
        EXPECT_TRUE(closed_and_oriented(m.mesh)) << name << " trial " << trial;
        EXPECT_GT(signed_volume(m.mesh), 0) << name << " trial " << trial;
        // A narrow bevel changes the volume little (either way: a concave edge's adds to it).
        EXPECT_NEAR(signed_volume(m.mesh), signed_volume(mesh), 0.01 * signed_volume(mesh))
            << name << " trial " << trial;
        EXPECT_EQ(all_triangles(m.mesh), triangles) << name << " trial " << trial;
      } catch (const Error& e) {
        ADD_FAILURE() << name << " trial " << trial << ": " << e.what();
      }
      const std::vector<int> vertices = {int(rng() % a.means.size()), int(rng() % a.means.size())};
      try {
        const Modelled m = bevel_vertices(mesh, vertices, width(0.02, segments));
        EXPECT_TRUE(closed_and_oriented(m.mesh)) << name << " trial " << trial;
        EXPECT_NEAR(signed_volume(m.mesh), signed_volume(mesh), 0.01 * signed_volume(mesh))
            << name << " trial " << trial;
      } catch (const Error& e) {
        ADD_FAILURE() << name << " vertices, trial " << trial << ": " << e.what();
      }
    }
  }
}

TEST(BevelEdges, WidthTypes) {
  const CovarianceMesh cube = make_sample("cube");
  BevelOptions o = width(25);
  o.width_type = BevelWidth::percent;  // a quarter of the edges beside it, 2 long
  EXPECT_GE(vertex_at(bevel_edges(cube, {{4, 5}}, o).mesh, Vec3(-1, -0.5, 1)), 0);
  // At a right angle the band across offsets o is o √2 wide and lies o / √2 from the edge.
  o = width(0.3 * std::sqrt(2.0));
  o.width_type = BevelWidth::width;
  EXPECT_GE(vertex_at(bevel_edges(cube, {{4, 5}}, o).mesh, Vec3(-1, -0.7, 1)), 0);
  o = width(0.3 / std::sqrt(2.0));
  o.width_type = BevelWidth::depth;
  EXPECT_GE(vertex_at(bevel_edges(cube, {{4, 5}}, o).mesh, Vec3(-1, -0.7, 1)), 0);
}

TEST(BevelEdges, ProfileShapes) {
  const CovarianceMesh cube = make_sample("cube");
  BevelOptions o = width(0.5, 2);
  o.profile = 0.25;  // straight: the middle of the chord
  EXPECT_GE(vertex_at(bevel_edges(cube, {{4, 5}}, o).mesh, Vec3(-1, -0.75, 0.75)), 0);
  o.profile = 1;  // the corner kept
  EXPECT_GE(vertex_at(bevel_edges(cube, {{4, 5}}, o).mesh, Vec3(-1, -1, 1)), 0);
}

TEST(BevelEdges, ClampStopsNewVerticesWhereTheyMeet) {
  const CovarianceMesh cube = make_sample("cube");
  // Edges 4–5 and 7–6 both slide a vertex along 4–7 (2 long), from each end: they meet at width 1.
  const Modelled m = bevel_edges(cube, {{4, 5}, {7, 6}}, width(3));
  EXPECT_EQ(m.summary,
            "bevelled 2 edges: 8 vertices in place of 4, 2 faces added; width clamped to 1 so that new "
            "vertices do not pass each other; 2 vertices that met merged, leaving 10 vertices and 7 faces");
  EXPECT_TRUE(closed_and_oriented(m.mesh));
  EXPECT_NEAR(signed_volume(m.mesh), 8 - 2 * 1.0 / 2 * 2, 1e-12);
  EXPECT_EQ(m.mesh.n_vertices(), 8u - 4u + 8u - 2u);
  BevelOptions o = width(3);
  o.clamp = false;
  EXPECT_EQ(error_of([&] {
              bevel_edges(cube, {{4, 5}, {7, 6}}, o);
            }),
            "a width of 3 would carry new vertices past each other on edge 4–7 (at most 1; clamp limits it)");
  o.width = 0.9;
  EXPECT_TRUE(closed_and_oriented(bevel_edges(cube, {{4, 5}, {7, 6}}, o).mesh));
}

// Open meshes: a flat grid of 3 × 3 unit quads, vertex 4 j + i at (i, j, 0), its faces facing +z;
// its boundary is one loop of 12 vertices (1 and 2 on the bottom side have valence 3, 0 is a corner
// of valence 2).
CovarianceMesh flat_grid(int n = 3, double sigma = 0.1) { return test::grid_mesh(n, n, sigma, true); }

/// Whether every directed edge of the faces appears once (manifold along edges and consistently
/// oriented) and no vertex is twice on the boundary loops (manifold at vertices).
bool manifold_and_oriented(const CovarianceMesh& mesh) {
  const MeshArrays a = arrays_of(mesh);
  std::map<std::pair<int, int>, int> directed;
  for (const auto& face : a.faces)
    for (size_t k = 0; k < face.size(); ++k)
      if (++directed[{face[k], face[(k + 1) % face.size()]}] > 1) return false;
  std::map<int, int> on_loops;
  for (const auto& loop : boundary_loops(mesh))
    for (int v : loop)
      if (++on_loops[v] > 1) return false;
  return true;
}

/// The number of vertices on the boundary loops.
size_t boundary_vertices(const CovarianceMesh& mesh) {
  size_t n = 0;
  for (const auto& loop : boundary_loops(mesh)) n += loop.size();
  return n;
}

/// The flat grid's faces: their area facing +z, and whether each faces +z.
double area_facing_up(const CovarianceMesh& mesh) {
  const MeshArrays a = arrays_of(mesh);
  double area = 0;
  for (int f = 0; f < a.n_faces(); ++f) area += newell_normal(a, f).z() / 2;
  return area;
}
bool all_face_up(const CovarianceMesh& mesh, bool or_flat = false) {
  const MeshArrays a = arrays_of(mesh);
  for (int f = 0; f < a.n_faces(); ++f)
    if (!(newell_normal(a, f).z() > (or_flat ? -1e-12 : 1e-12))) return false;
  return true;
}

TEST(BevelAtBoundaries, ABoundaryEdgeGetsABandInItsFaceBetweenItAndTheNewEdge) {
  const CovarianceMesh grid = flat_grid();
  // Edge 1–2 on the bottom: face {1, 2, 6, 5} gets its new edge at y = 0.25, on edges 1–5 and 2–6;
  // the band {1, 2, b, a} lies between it and the edge, whose ends stay on the boundary; face {0, 1, 5, 4}
  // and face {2, 3, 7, 6} get the band's end corners on their edges.
  const Modelled one = bevel_edges(grid, {{1, 2}}, width(0.25));
  EXPECT_EQ(one.mesh.n_vertices(), 16u + 2);
  EXPECT_EQ(one.mesh.n_faces(), 9u + 1);
  EXPECT_TRUE(manifold_and_oriented(one.mesh));
  EXPECT_EQ(boundary_loops(one.mesh).size(), 1u);
  EXPECT_EQ(boundary_vertices(one.mesh), 12u);
  EXPECT_TRUE(all_face_up(one.mesh));
  EXPECT_NEAR(area_facing_up(one.mesh), 9, 1e-12);
  EXPECT_EQ(one.selection, (std::vector<int>{16, 17}));
  EXPECT_EQ(vertex_at(one.mesh, Vec3(1, 0.25, 0)) + vertex_at(one.mesh, Vec3(2, 0.25, 0)), 16 + 17);
  EXPECT_EQ(one.summary, "bevelled 1 edge: 2 vertices in place of 0, 1 face added");
  // With 2 segments the band's middle rail meets the end edges half way.
  const Modelled two = bevel_edges(grid, {{1, 2}}, width(0.25, 2));
  EXPECT_EQ(two.mesh.n_vertices(), 16u + 4);
  EXPECT_EQ(two.mesh.n_faces(), 9u + 2);
  EXPECT_TRUE(manifold_and_oriented(two.mesh));
  EXPECT_EQ(boundary_vertices(two.mesh), 12u);
  EXPECT_TRUE(all_face_up(two.mesh));
  EXPECT_NEAR(area_facing_up(two.mesh), 9, 1e-12);
  for (const Vec3& p : {Vec3(1, 0.25, 0), Vec3(2, 0.25, 0), Vec3(1, 0.125, 0), Vec3(2, 0.125, 0)})
    EXPECT_GE(vertex_at(two.mesh, p), 16) << p.transpose();
}

TEST(BevelAtBoundaries, AnInnerEdgeEndingOnTheBoundarySplitsItsEndAlongTheBoundary) {
  const CovarianceMesh grid = flat_grid();
  // Edge 1–5: vertex 1 becomes (0.75, 0) and (1.25, 0) on the boundary, the band's end between them
  // open; vertex 5 (valence 4) becomes, as in Blender, a vertex on each of its other three edges, a
  // triangle closing its corner (with area: the one across lies 0.25 along the edge that runs on).
  const Modelled m = bevel_edges(grid, {{1, 5}}, width(0.25));
  EXPECT_EQ(m.mesh.n_vertices(), 16u - 2 + 2 + 3);
  EXPECT_EQ(m.mesh.n_faces(), 9u + 1 + 1);
  EXPECT_TRUE(manifold_and_oriented(m.mesh));
  EXPECT_EQ(boundary_loops(m.mesh).size(), 1u);
  EXPECT_EQ(boundary_vertices(m.mesh), 12u - 1 + 2);
  EXPECT_TRUE(all_face_up(m.mesh));  // no face without area
  EXPECT_NEAR(area_facing_up(m.mesh), 9, 1e-12);
  EXPECT_EQ(vertex_at(m.mesh, Vec3(1, 0, 0)), -1);
  EXPECT_EQ(vertex_at(m.mesh, Vec3(1, 1, 0)), -1);
  for (const Vec3& p : {Vec3(0.75, 0, 0), Vec3(1.25, 0, 0), Vec3(0.75, 1, 0), Vec3(1.25, 1, 0), Vec3(1, 1.25, 0)})
    EXPECT_GE(vertex_at(m.mesh, p), 14) << p.transpose();
}

TEST(BevelEdges, TheEndsOfOneEdgeAmongFourEdgesLeaveNoFaceWithoutArea) {
  // Edge 6–7 inside a 4 × 4 grid, both ends of valence 4 with their other edges in line: each end gives
  // way to a vertex on each of its three other edges (Blender's), so the triangle closing it has area.
  const CovarianceMesh grid = flat_grid(4);
  for (int segments : {1, 2}) {
    const Modelled m = bevel_edges(grid, {{6, 7}}, width(0.2, segments));
    EXPECT_EQ(m.mesh.n_vertices(), 25u - 2 + 2 * (3 + segments - 1)) << segments;
    EXPECT_EQ(m.mesh.n_faces(), 16u + segments + 2) << segments;
    EXPECT_TRUE(manifold_and_oriented(m.mesh));
    EXPECT_TRUE(all_face_up(m.mesh)) << segments;
    EXPECT_NEAR(area_facing_up(m.mesh), 16, 1e-12);
    for (const Vec3& p : {Vec3(0.8, 1, 0), Vec3(2.2, 1, 0)}) EXPECT_GE(vertex_at(m.mesh, p), 23) << p.transpose();
  }
}

TEST(BevelAtBoundaries, TheWholeRimOfASideBecomesABandAlongIt) {
  const CovarianceMesh grid = flat_grid();
  // The bottom side 0–1–2–3: at 1 and 2 the two bands share a vertex on the inner edge; at the
  // corners 0 and 3 the band ends on the side edge, which gains its end; the new rail is 4 vertices at
  // y = 0.25.
  for (int segments : {1, 3}) {
    const Modelled m = bevel_edges(grid, {{0, 1}, {1, 2}, {2, 3}}, width(0.25, segments));
    EXPECT_EQ(m.mesh.n_vertices(), 16u + 4 * size_t(segments));
    EXPECT_EQ(m.mesh.n_faces(), 9u + 3 * size_t(segments));
    EXPECT_TRUE(manifold_and_oriented(m.mesh));
    EXPECT_EQ(boundary_loops(m.mesh).size(), 1u);
    EXPECT_EQ(boundary_vertices(m.mesh), 12u + 2 * size_t(segments));
    EXPECT_TRUE(all_face_up(m.mesh));
    EXPECT_NEAR(area_facing_up(m.mesh), 9, 1e-12);
    for (int i = 0; i <= 3; ++i) EXPECT_GE(vertex_at(m.mesh, Vec3(i, 0.25, 0)), 16) << i;
  }
}

TEST(BevelAtBoundaries, BoundaryVerticesAreCutByAPolygonOpenOnTheBoundarySide) {
  const CovarianceMesh grid = flat_grid();
  // Vertex 1 (valence 3): new vertices on its three edges, a triangle in place of its corners,
  // whose edge from (0.75, 0) to (1.25, 0) is on the boundary.
  const Modelled three = bevel_vertices(grid, {1}, width(0.25));
  EXPECT_EQ(three.mesh.n_vertices(), 16u - 1 + 3);
  EXPECT_EQ(three.mesh.n_faces(), 9u + 1);
  EXPECT_TRUE(manifold_and_oriented(three.mesh));
  EXPECT_EQ(boundary_vertices(three.mesh), 12u - 1 + 2);
  EXPECT_TRUE(all_face_up(three.mesh));
  EXPECT_NEAR(area_facing_up(three.mesh), 9, 1e-12);
  for (const Vec3& p : {Vec3(0.75, 0, 0), Vec3(1.25, 0, 0), Vec3(1, 0.25, 0)})
    EXPECT_GE(vertex_at(three.mesh, p), 15) << p.transpose();
  EXPECT_EQ(three.summary, "bevelled 1 vertex: 3 vertices in place of 1, 1 face added");
  // Corner 0 (valence 2), as Blender bevels it: its one face's corner cut off, the cut on the boundary.
  const Modelled two = bevel_vertices(grid, {0}, width(0.25));
  EXPECT_EQ(two.mesh.n_vertices(), 16u - 1 + 2);
  EXPECT_EQ(two.mesh.n_faces(), 9u);
  EXPECT_TRUE(manifold_and_oriented(two.mesh));
  EXPECT_EQ(boundary_vertices(two.mesh), 12u - 1 + 2);
  EXPECT_NEAR(area_facing_up(two.mesh), 9 - 0.25 * 0.25 / 2, 1e-12);
  // With 2 segments the corner is rounded: the profile's middle on the quarter circle about (0.25, 0.25).
  const Modelled round = bevel_vertices(grid, {0}, width(0.25, 2));
  EXPECT_EQ(round.mesh.n_vertices(), 16u - 1 + 3);
  EXPECT_EQ(round.mesh.n_faces(), 9u);
  EXPECT_TRUE(manifold_and_oriented(round.mesh));
  EXPECT_TRUE(all_face_up(round.mesh));
  const double inward = 0.25 * (1 - 1 / std::sqrt(2.0));
  EXPECT_GE(vertex_at(round.mesh, Vec3(inward, inward, 0)), 15);
}

TEST(BevelAtBoundaries, CreasesFollowTheirEdgesAndTheOperationListGivesTheSameBevel) {
  CovarianceMesh grid = flat_grid();
  grid.sharpness.set_crease(0, 1, 2.0);  // on the boundary
  grid.sharpness.set_crease(1, 5, 3.0);  // inner
  const Modelled m = bevel_vertices(grid, {1}, width(0.25));
  const int on_boundary = vertex_at(m.mesh, Vec3(0.75, 0, 0)), inner = vertex_at(m.mesh, Vec3(1, 0.25, 0));
  EXPECT_EQ(m.mesh.sharpness.crease(0, on_boundary), 2.0);
  EXPECT_EQ(m.mesh.sharpness.crease(inner, 4), 3.0);  // vertex 5 is 4 once 1 is gone
  EXPECT_EQ(m.mesh.sharpness.creases.size(), 2u);

  const Modelled listed =
      OperationList::parse(R"([{"op":"bevel","edges":[[1,2]],"width":0.25,"segments":2}])", "ops.json").apply(grid);
  const Modelled direct = bevel_edges(grid, {{1, 2}}, width(0.25, 2));
  EXPECT_EQ(arrays_of(listed.mesh).faces, arrays_of(direct.mesh).faces);
  EXPECT_EQ(arrays_of(listed.mesh).means, arrays_of(direct.mesh).means);
}

TEST(BevelAtBoundaries, NewVerticesGetTheNineDimensionalBlends) {
  const CovarianceMesh grid = with_random_covariances(flat_grid(), 5);
  const MeshArrays before = arrays_of(grid);
  const Modelled m = bevel_edges(grid, {{1, 2}}, width(0.25, 2));
  const MeshArrays after = arrays_of(m.mesh);
  // On edge 1–5 (1 long) at 0.25: 0.75 q_1 + 0.25 q_5; the middle rail half way along the end edge.
  const int rail = vertex_at(m.mesh, Vec3(1, 0.25, 0)), middle = vertex_at(m.mesh, Vec3(1, 0.125, 0));
  ASSERT_GE(rail, 0);
  ASSERT_GE(middle, 0);
  EXPECT_TRUE(
      m.mesh.covariances[size_t(rail)].isApprox(blend_gaussians(before, {{1, 0.75}, {5, 0.25}}).covariance, 1e-12));
  EXPECT_TRUE(m.mesh.covariances[size_t(middle)].isApprox(
      blend_gaussians(after, {{rail, 0.5}, {vertex_at(m.mesh, Vec3(1, 0, 0)), 0.5}}).covariance, 1e-12));
  const Modelled v = bevel_vertices(grid, {1}, width(0.25));
  const int on_boundary = vertex_at(v.mesh, Vec3(0.75, 0, 0));
  ASSERT_GE(on_boundary, 0);
  EXPECT_TRUE(v.mesh.covariances[size_t(on_boundary)].isApprox(
      blend_gaussians(before, {{1, 0.75}, {0, 0.25}}).covariance, 1e-12));
}

TEST(BevelAtBoundaries, ATooWideBevelWithoutClampIsRefusedAndChangesNothing) {
  const CovarianceMesh grid = flat_grid();
  const MeshArrays before = arrays_of(grid);
  BevelOptions o = width(1.5);
  o.clamp = false;
  EXPECT_EQ(error_of([&] {
              bevel_edges(grid, {{1, 2}}, o);
            }),
            "a width of 1.5 would carry new vertices past each other on edge 1–5 (at most 1; clamp limits it)");
  EXPECT_EQ(error_of([&] { bevel_vertices(grid, {0}, o); }),
            "a width of 1.5 would carry new vertices past each other on edge 0–1 (at most 1; clamp limits it)");
  EXPECT_EQ(arrays_of(grid).faces, before.faces);
  EXPECT_EQ(arrays_of(grid).means, before.means);
  o.clamp = true;
  EXPECT_NE(bevel_edges(grid, {{1, 2}}, o).summary.find("width clamped to 1"), std::string::npos);
}

TEST(BevelAtBoundaries, AnySetOfEdgesOrVerticesOnOpenMeshesStaysManifoldWithItsBoundaryLoops) {
  std::mt19937 rng(5);
  const CovarianceMesh cylinder = make_sample("cylinder");
  std::vector<int> cap;  // the octagon of one cap
  for (int f = 0; f < int(cylinder.n_faces()); ++f)
    if (arrays_of(cylinder).faces[size_t(f)].size() == 8) cap.push_back(f);
  // A flat half wheel: a boundary vertex of valence 8 at its hub.
  std::vector<Vec3> wheel_points{Vec3::Zero()};
  std::vector<std::vector<int>> spokes;
  for (int k = 0; k <= 6; ++k) wheel_points.emplace_back(std::cos(M_PI * k / 6), std::sin(M_PI * k / 6), 0);
  for (int k = 1; k <= 6; ++k) spokes.push_back({0, k, k + 1});
  const CovarianceMesh wheel = make_covariance_mesh(
      wheel_points, std::vector<Mat3>(wheel_points.size(), 0.01 * Mat3::Identity()), spokes, "half wheel");
  const std::vector<std::pair<std::string, CovarianceMesh>> meshes = {
      {"grid", grid_mesh(6, 5)},     {"flat grid", flat_grid(4)},
      {"half wheel", wheel},         {"triangle grid", test::triangle_grid_mesh(5, 4)},
      {"cone", make_sample("cone")}, {"open cylinder", delete_faces(cylinder, {cap[0]}).mesh}};
  for (const auto& [name, mesh] : meshes) {
    const bool flat = name == "flat grid" || name == "half wheel";
    const MeshArrays a = arrays_of(mesh);
    const size_t loops = boundary_loops(mesh).size();
    const bool triangles = all_triangles(mesh);
    std::vector<std::array<int, 2>> edges, rim;
    for (const auto& face : a.faces)
      for (size_t k = 0; k < face.size(); ++k) {
        const int x = face[k], y = face[(k + 1) % face.size()];
        if (x < y || !has_edge(directed_edges(a), y, x)) edges.push_back({std::min(x, y), std::max(x, y)});
      }
    for (const auto& loop : boundary_loops(mesh))
      for (size_t k = 0; k < loop.size(); ++k) rim.push_back({loop[k], loop[(k + 1) % loop.size()]});
    for (int trial = 0; trial < 30; ++trial) {
      std::vector<std::array<int, 2>> chosen;
      const size_t count = 1 + rng() % 5;
      for (size_t i = 0; i < count; ++i)
        chosen.push_back(rng() % 2 ? rim[rng() % rim.size()] : edges[rng() % edges.size()]);
      if (trial % 5 == 0) chosen = rim;  // a whole rim
      const int segments = 1 + int(rng() % 3);
      try {
        const Modelled m = bevel_edges(mesh, chosen, width(0.05, segments));
        EXPECT_TRUE(manifold_and_oriented(m.mesh)) << name << " trial " << trial;
        EXPECT_EQ(boundary_loops(m.mesh).size(), loops) << name << " trial " << trial;
        EXPECT_EQ(all_triangles(m.mesh), triangles) << name << " trial " << trial;
        if (flat) {  // the bands lie in the faces; an end on a bent boundary cuts its corner
          EXPECT_TRUE(all_face_up(m.mesh, true)) << name << " trial " << trial;
          if (name == "flat grid") {
            EXPECT_NEAR(area_facing_up(m.mesh), area_facing_up(mesh), 1e-9) << name << " trial " << trial;
          } else {
            EXPECT_LT(area_facing_up(m.mesh), area_facing_up(mesh) + 1e-9) << name << " trial " << trial;
          }
        }
      } catch (const Error& e) {
        ADD_FAILURE() << name << " trial " << trial << ": " << e.what();
      }
      const std::vector<int> vertices = {rim[rng() % rim.size()][0], int(rng() % a.means.size())};
      try {
        const Modelled m = bevel_vertices(mesh, vertices, width(0.05, segments));
        EXPECT_TRUE(manifold_and_oriented(m.mesh)) << name << " vertices, trial " << trial;
        EXPECT_EQ(boundary_loops(m.mesh).size(), loops) << name << " vertices, trial " << trial;
        if (flat) {
          EXPECT_TRUE(all_face_up(m.mesh, true)) << name << " vertices, trial " << trial;
        }
      } catch (const Error& e) {
        ADD_FAILURE() << name << " vertices, trial " << trial << ": " << e.what();
      }
    }
  }
}

TEST(Bevel, RefusalsNameTheElementAndChangeNothing) {
  const CovarianceMesh cube = make_sample("cube");
  const MeshArrays before = arrays_of(cube);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(error_of([&] { bevel_edges(cube, {{0, 6}}, width(0.1)); }), "edge 0–6 is not in the mesh");
  EXPECT_EQ(error_of([&] { bevel_edges(cube, {{0, 99}}, width(0.1)); }), "edge 0–99 is not in the mesh");
  EXPECT_EQ(error_of([&] { bevel_edges(cube, {}, width(0.1)); }), "no edges are selected");
  EXPECT_EQ(error_of([&] { bevel_edges(cube, {{4, 5}}, width(0)); }), "width 0 is not a positive number");
  EXPECT_EQ(error_of([&] { bevel_edges(cube, {{4, 5}}, width(-1)); }), "width -1 is not a positive number");
  EXPECT_EQ(error_of([&] { bevel_edges(cube, {{4, 5}}, width(nan)); }), "width nan is not a positive number");
  EXPECT_EQ(error_of([&] { bevel_edges(cube, {{4, 5}}, width(0.1, 0)); }), "segments 0 is not from 1 to 100");
  BevelOptions o = width(0.1);
  o.profile = 0;
  EXPECT_EQ(error_of([&] { bevel_edges(cube, {{4, 5}}, o); }), "profile 0 is not in (0, 1]");
  EXPECT_EQ(error_of([&] { bevel_vertices(cube, {8}, width(0.1)); }), "vertex 8 is not in the mesh (8 vertices)");
  EXPECT_EQ(error_of([&] { bevel_vertices(cube, {0}, width(nan)); }), "width nan is not a positive number");
  EXPECT_EQ(error_of([&] { bevel_vertices(cube, {0}, width(0.1, 0)); }), "segments 0 is not from 1 to 100");
  o.profile = 0.5;
  o.width_type = BevelWidth::depth;
  EXPECT_EQ(error_of([&] { bevel_vertices(cube, {0}, o); }),
            "the width type \"depth\" is for edges; a vertex bevel takes \"offset\" or \"percent\"");
  const MeshArrays after = arrays_of(cube);
  EXPECT_EQ(after.faces, before.faces);
  EXPECT_EQ(after.means, before.means);
  EXPECT_EQ(after.covariances, before.covariances);
}

TEST(Bevel, TheInputIsNeverChanged) {
  const CovarianceMesh cube = make_sample("cube");
  const MeshArrays before = arrays_of(cube);
  bevel_edges(cube, {{4, 5}}, width(0.25, 3));
  bevel_vertices(cube, {4}, width(0.25, 3));
  EXPECT_EQ(arrays_of(cube).faces, before.faces);
  EXPECT_EQ(arrays_of(cube).means, before.means);
}

TEST(BevelOperationList, EdgesAndVerticesAsTheCallsGiveThem) {
  const CovarianceMesh cube = make_sample("cube");
  BevelOptions o = width(0.25, 2);
  o.profile = 0.7;
  o.crease = 1.5;
  const Modelled direct = bevel_edges(cube, {{4, 5}}, o);
  const Modelled listed =
      OperationList::parse(
          R"([{"op":"bevel","edges":[[4,5]],"width":0.25,"segments":2,"profile":0.7,"crease":1.5,"clamp":true}])",
          "ops.json")
          .apply(cube);
  EXPECT_EQ(arrays_of(listed.mesh).faces, arrays_of(direct.mesh).faces);
  EXPECT_EQ(arrays_of(listed.mesh).means, arrays_of(direct.mesh).means);
  EXPECT_EQ(listed.mesh.sharpness.creases, direct.mesh.sharpness.creases);
  const Modelled vertex =
      OperationList::parse(R"([{"op":"bevel","vertices":[4],"width":50,"width_type":"percent"}])", "ops.json")
          .apply(cube);
  EXPECT_EQ(vertex.mesh.n_vertices(), 10u);
  EXPECT_GE(vertex_at(vertex.mesh, Vec3(-1, -1, 0)), 0);

  const auto parse_error = [](const std::string& text) {
    return error_of([&] { OperationList::parse(text, "ops.json"); });
  };
  EXPECT_EQ(parse_error(R"([{"op":"bevel","edges":[[4,5]],"width":-1}])"),
            "ops.json: ops[0] (bevel): \"width\" must be positive");
  EXPECT_EQ(parse_error(R"([{"op":"bevel","edges":[[4,5]],"width":0.1,"segments":0}])"),
            "ops.json: ops[0] (bevel): \"segments\" must be an integer from 1 to 100, got 0");
  EXPECT_EQ(parse_error(R"([{"op":"bevel","edges":[[4,5]],"width":0.1,"profile":1.5}])"),
            "ops.json: ops[0] (bevel): \"profile\" must be a number in (0, 1]");
  EXPECT_EQ(parse_error(R"([{"op":"bevel","vertices":[4],"width":0.1,"crease":1}])"),
            "ops.json: ops[0] (bevel): unknown key 'crease'");
  EXPECT_EQ(parse_error(R"([{"op":"bevel","edges":[[4,5]],"width":0.1,"width_type":"wide"}])"),
            "ops.json: ops[0] (bevel): \"width_type\" must be \"offset\", \"width\", \"depth\" or \"percent\"");
  EXPECT_EQ(parse_error(R"([{"op":"bevel","edges":[[4,5]],"vertices":[4],"width":0.1}])"),
            "ops.json: ops[0] (bevel): give one of \"edges\" or \"vertices\"");
  EXPECT_EQ(error_of([&] {
              OperationList::parse(R"([{"op":"bevel","edges":[[0,6]],"width":0.1}])", "ops.json").apply(cube);
            }),
            "ops.json: ops[0] (bevel): edge 0–6 is not in the mesh");
}

// The faces a face-mode editor goes on with: the band, not the face it shrank (as Blender selects).
TEST(BevelEdges, TheBandIsTheFacesSelected) {
  const CovarianceMesh cube = make_sample("cube");
  const Modelled m = bevel_edges(cube, {{4, 5}, {5, 6}, {6, 7}, {7, 4}}, width(0.2));
  EXPECT_EQ(m.selected_faces, (std::vector<int>{6, 7, 8, 9}));
}

}  // namespace
}  // namespace gps
