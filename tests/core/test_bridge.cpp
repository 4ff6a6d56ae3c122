#include "core/modelling/bridge.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/support/error.h"
#include "core/modelling/samples.h"
#include "core/modelling/inset.h"
#include "core/modelling/mesh_queries.h"
#include "core/modelling/operation_list.h"
#include "tests/support/error_of.h"
#include "tests/support/test_meshes.h"
#include "tests/support/mesh_checks.h"

namespace gps {
namespace {

using test::signed_volume;

using test::error_of;
using V = std::vector<int>;

using test::boundary_edges_of_oriented;

// The 24 × 12 torus (vertex i·12 + j on ring i) cut into two open tubes by removing the bands of
// faces between rings 0 and 1 and between rings 12 and 13.
CovarianceMesh cut_torus() {
  MeshArrays a = arrays_of(make_sample("torus"));
  std::vector<std::vector<int>> kept;
  for (int f = 0; f < a.n_faces(); ++f)
    if (f / 12 != 0 && f / 12 != 12) kept.push_back(a.faces[size_t(f)]);
  a.faces = kept;
  return build_mesh(a);
}

V ring(int i) {
  V r;
  for (int j = 0; j < 12; ++j) r.push_back(12 * i + j);
  return r;
}

TEST(Bridge, TwoTubesCloseIntoARing) {
  const CovarianceMesh cut = cut_torus();
  ASSERT_EQ(boundary_loops(cut).size(), 4u);
  EXPECT_EQ(boundary_edges_of_oriented(cut), 48);
  // The first loop rotated, the second reversed and rotated: the pairing is found all the same.
  V a = ring(0), b = ring(1);
  std::rotate(a.begin(), a.begin() + 5, a.end());
  std::reverse(b.begin(), b.end());
  std::rotate(b.begin(), b.begin() + 3, b.end());
  const Modelled once = bridge(cut, a, b);
  EXPECT_EQ(once.mesh.n_faces(), 276u);
  EXPECT_EQ(boundary_edges_of_oriented(once.mesh), 24);
  EXPECT_EQ(once.summary, "bridged two loops of 12 vertices: 12 faces added");
  V both = ring(0);
  both.insert(both.end(), b.begin(), b.end());
  std::sort(both.begin(), both.end());
  EXPECT_EQ(once.selection, both);
  const Modelled closed = bridge(once.mesh, ring(13), ring(12));
  EXPECT_EQ(closed.mesh.n_faces(), 288u);
  EXPECT_EQ(closed.mesh.n_vertices(), 288u);
  EXPECT_EQ(boundary_edges_of_oriented(closed.mesh), 0);
  // Paired vertices are the nearest ones: vertex j of ring 0 with vertex j of ring 1.
  const DirectedEdges edges = directed_edges(arrays_of(closed.mesh));
  for (int j = 0; j < 12; ++j) {
    EXPECT_TRUE(has_edge(edges, j, 12 + j)) << j;
    EXPECT_TRUE(has_edge(edges, 144 + j, 156 + j)) << j;
  }
}

TEST(Bridge, BridgeSelectedFindsTheTwoLoops) {
  const CovarianceMesh cut = cut_torus();
  V selected = ring(12);
  const V other = ring(13);
  selected.insert(selected.end(), other.begin(), other.end());
  const Modelled r = bridge_selected(cut, selected);
  EXPECT_EQ(r.mesh.n_faces(), 276u);
  EXPECT_EQ(boundary_edges_of_oriented(r.mesh), 24);
  EXPECT_EQ(boundary_loops(r.mesh).size(), 2u);
}

TEST(Bridge, OpenChainsMakeAStrip) {
  // Two unit quads a unit apart: the right edge of the first bridges to the left edge of the second.
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {3, 0, 0}, {3, 1, 0}, {2, 1, 0}};
  const CovarianceMesh quads =
      make_covariance_mesh(p, std::vector<Mat3>(8, 0.1 * Mat3::Identity()), {{0, 1, 2, 3}, {4, 5, 6, 7}});
  for (const Modelled& r :
       {bridge(quads, {1, 2}, {7, 4}), bridge(quads, {2, 1}, {4, 7}), bridge_selected(quads, {1, 2, 4, 7})}) {
    EXPECT_EQ(r.mesh.n_faces(), 3u);
    EXPECT_EQ(boundary_edges_of_oriented(r.mesh), 8);
    EXPECT_EQ(r.selection, (V{1, 2, 4, 7}));
    EXPECT_EQ(arrays_of(r.mesh).faces[2], (V{2, 1, 4, 7}));
    EXPECT_EQ(r.summary, "bridged two chains of 2 vertices: 1 face added");
  }
}

TEST(Bridge, RefusalsNameTheProblemAndChangeNothing) {
  const CovarianceMesh cut = cut_torus();
  V eight = ring(1);
  eight.resize(8);
  EXPECT_EQ(error_of([&] { bridge(cut, ring(0), eight); }), "cannot bridge a closed boundary loop to an open chain");
  EXPECT_EQ(error_of([&] { bridge(cut, ring(0), ring(0)); }), "vertex 0 is in both loops");
  EXPECT_EQ(error_of([&] { bridge(cut, ring(0), {12, 13, 14, 13}); }), "vertex 13 is listed twice in a loop");
  EXPECT_EQ(error_of([&] { bridge(cut, {}, {}); }), "a chain to bridge needs at least 2 vertices");
  EXPECT_EQ(error_of([&] { bridge(cut, ring(0), ring(5)); }), "vertex 60 is not on a boundary");
  EXPECT_EQ(error_of([&] {
              bridge(cut, ring(0), {12, 13, 14, 16, 17, 18, 19, 20, 21, 22, 23, 300});
            }),
            "vertex 300 is not in the mesh (288 vertices)");
  V gap = ring(1);
  gap[11] = 11;
  const std::string apart = error_of([&] { bridge(cut, ring(12), gap); });
  EXPECT_NE(apart.find("is not joined to vertex 11 along the boundary: not one loop or chain"), std::string::npos)
      << apart;
  EXPECT_EQ(error_of([&] { bridge_selected(cut, ring(0)); }),
            "the selection makes 1 boundary loops or chains; bridge needs exactly 2");
  V twelve_and_two = ring(0);
  twelve_and_two.insert(twelve_and_two.end(), {13, 14});
  EXPECT_EQ(error_of([&] { bridge_selected(cut, twelve_and_two); }),
            "cannot bridge a closed boundary loop to an open chain");
  // An open chain of 4 along a strip of two quads, and a whole loop of 4 around a separate quad.
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0},
                               {2, 1, 0}, {0, 0, 2}, {1, 0, 2}, {1, 1, 2}, {0, 1, 2}};
  const CovarianceMesh pieces = make_covariance_mesh(p, std::vector<Mat3>(10, 0.1 * Mat3::Identity()),
                                                     {{0, 1, 4, 3}, {1, 2, 5, 4}, {6, 7, 8, 9}});
  EXPECT_EQ(error_of([&] {
              bridge(pieces, {0, 1, 2, 5}, {6, 7, 8, 9});
            }),
            "cannot bridge a closed boundary loop to an open chain");
  EXPECT_EQ(cut.n_faces(), 264u);
}

// V − E + F of a mesh (2 for a sphere, 0 for a torus).
int euler_characteristic(const CovarianceMesh& m) {
  const MeshArrays a = arrays_of(m);
  std::set<uint64_t> edges;
  for (const auto& f : a.faces)
    for (size_t k = 0; k < f.size(); ++k) edges.insert(edge_key(f[k], f[(k + 1) % f.size()]));
  return a.n_vertices() - int(edges.size()) + a.n_faces();
}

// Two polygons of n and m corners on circles of radius 1 at z = 0 (facing down) and z = 1 (facing
// up; turned by `twist` radians); with `fans`, each a fan of triangles around a centre vertex
// (the last two vertices). Vertices 0..n−1 are the lower rim, n..n+m−1 the upper.
CovarianceMesh two_polygons(int n, int m, double twist, bool fans) {
  std::vector<Vec3> p;
  for (int k = 0; k < n; ++k) p.emplace_back(std::cos(2 * M_PI * k / n), std::sin(2 * M_PI * k / n), 0);
  for (int k = 0; k < m; ++k) p.emplace_back(std::cos(2 * M_PI * k / m + twist), std::sin(2 * M_PI * k / m + twist), 1);
  std::vector<std::vector<int>> faces;
  if (fans) {
    p.emplace_back(0, 0, 0);
    p.emplace_back(0, 0, 1);
    for (int k = 0; k < n; ++k) faces.push_back({n + m, (k + 1) % n, k});
    for (int k = 0; k < m; ++k) faces.push_back({n + m + 1, n + k, n + (k + 1) % m});
  } else {
    faces.push_back({});
    for (int k = n - 1; k >= 0; --k) faces.back().push_back(k);
    faces.push_back({});
    for (int k = 0; k < m; ++k) faces.back().push_back(n + k);
  }
  return make_covariance_mesh(p, std::vector<Mat3>(p.size(), 0.01 * Mat3::Identity()), faces);
}

V range(int from, int to) {
  V r;
  for (int v = from; v < to; ++v) r.push_back(v);
  return r;
}

TEST(Bridge, LoopsOfEightAndSevenCloseADrum) {
  for (const bool fans : {false, true}) {
    const CovarianceMesh drum = two_polygons(8, 7, 2.0, fans);
    const Modelled r = bridge(drum, range(0, 8), range(8, 15));
    EXPECT_EQ(boundary_edges_of_oriented(r.mesh), 0) << fans;
    EXPECT_EQ(euler_characteristic(r.mesh), 2) << fans;
    EXPECT_GT(signed_volume(r.mesh), 0) << fans;
    const MeshArrays a = arrays_of(r.mesh);
    size_t quads = 0, triangles = 0;
    for (size_t f = size_t(drum.n_faces()); f < a.faces.size(); ++f) (a.faces[f].size() == 4 ? quads : triangles)++;
    if (fans) {  // a mesh of triangles stays one: each of the 7 quads in two, and the 1 triangle
      EXPECT_EQ(quads, 0u);
      EXPECT_EQ(triangles, 15u);
      EXPECT_EQ(r.summary,
                "bridged two loops of 8 and 7 vertices: 15 faces added (1 triangle spreading the difference)");
    } else {
      EXPECT_EQ(quads, 7u);
      EXPECT_EQ(triangles, 1u);
      EXPECT_EQ(r.summary,
                "bridged two loops of 8 and 7 vertices: 8 faces added (1 triangle spreading the difference)");
    }
    // The band's edges between the loops go to the nearest part of the twisted upper loop: none
    // longer than the step between neighbouring angles allows.
    int across = 0;
    for (const std::vector<int>& face : a.faces)
      for (size_t k = 0; k < face.size(); ++k) {
        const int u = face[k], v = face[(k + 1) % face.size()];
        if (u >= 8 || v < 8 || v >= 15) continue;
        ++across;
        if (!fans) {  // the triangles' diagonals reach further
          EXPECT_LT((a.means[size_t(u)] - a.means[size_t(v)]).norm(), std::hypot(1.0, 2 * std::sin(M_PI / 8)))
              << u << "–" << v;
        }
      }
    EXPECT_EQ(across, fans ? 15 : 8);  // the triangles' diagonals cross too
    EXPECT_EQ(r.selection, range(0, 15));
    // Either way round, and the editor's selection of both loops, give the same faces.
    EXPECT_EQ(arrays_of(bridge_selected(drum, range(0, 15)).mesh).faces, a.faces);
    EXPECT_EQ(boundary_edges_of_oriented(bridge(drum, range(8, 15), range(0, 8)).mesh), 0);
  }
}

TEST(Bridge, TrianglesSpreadEvenly) {
  // 12 against 5: 7 triangles, at most one quad between two of them and never two quads in a row.
  const CovarianceMesh drum = two_polygons(12, 5, 0.3, false);
  const MeshArrays a = arrays_of(bridge(drum, range(0, 12), range(12, 17)).mesh);
  std::vector<char> triangle_at(12, 0);  // by the lower rim's step k → k + 1
  for (size_t f = 2; f < a.faces.size(); ++f) {
    const std::vector<int>& face = a.faces[f];
    int lower = -1;
    for (size_t k = 0; k < face.size(); ++k)
      if (face[k] < 12 && face[(k + 1) % face.size()] < 12) lower = face[(k + 1) % face.size()];
    ASSERT_GE(lower, 0);
    triangle_at[size_t(lower)] = face.size() == 3;
  }
  EXPECT_EQ(std::count(triangle_at.begin(), triangle_at.end(), 1), 7);
  for (size_t k = 0; k < 12; ++k) EXPECT_TRUE(triangle_at[k] || triangle_at[(k + 1) % 12]) << k;
}

TEST(Bridge, TwoFacesOfACubeMakeATubeThroughIt) {
  // The cube's bottom and top faces (0 and 1) inset, then bridged: a hole through it.
  const CovarianceMesh inset = inset_faces(test::cube_mesh(), {0, 1}, 0.5).mesh;
  const Modelled r = bridge_faces(inset, {0, 1});
  EXPECT_EQ(r.mesh.n_vertices(), 16u);
  EXPECT_EQ(r.mesh.n_faces(), inset.n_faces() - 2 + 4);
  EXPECT_EQ(boundary_edges_of_oriented(r.mesh), 0);
  EXPECT_EQ(euler_characteristic(r.mesh), 0);  // genus 1
  EXPECT_GT(signed_volume(r.mesh), 0);
  EXPECT_NEAR(signed_volume(r.mesh), 8 - 2, 1e-12);  // the 2 × 2 cube less the 1 × 1 hole through it
  EXPECT_EQ(r.selection, range(8, 16));
  EXPECT_EQ(r.summary, "deleted 2 faces, bridged two loops of 4 vertices: 4 faces added");
  // The editor's selection of their corners does the same.
  EXPECT_EQ(arrays_of(bridge_selected(inset, range(8, 16)).mesh).faces, arrays_of(r.mesh).faces);
  // As a listed operation.
  const Modelled listed = OperationList::parse(R"([{"op":"bridge","faces":[1,0]}])", "ops.json").apply(inset);
  EXPECT_EQ(arrays_of(listed.mesh).faces, arrays_of(r.mesh).faces);
}

TEST(Bridge, FaceRegionsTakeTheirInnerVerticesWithThem) {
  // Inset twice: each region is the innermost face and the ring around it (5 faces, 4 inner vertices).
  const Modelled once = inset_faces(test::cube_mesh(), {0, 1}, 0.4);
  const Modelled twice = inset_faces(once.mesh, {0, 1}, 0.2);
  V corners = once.selection;
  corners.insert(corners.end(), twice.selection.begin(), twice.selection.end());
  const V faces = faces_within(twice.mesh, corners);
  ASSERT_EQ(faces.size(), 10u);
  const Modelled r = bridge_faces(twice.mesh, faces);
  EXPECT_EQ(r.mesh.n_vertices(), 16u);
  EXPECT_EQ(boundary_edges_of_oriented(r.mesh), 0);
  EXPECT_EQ(euler_characteristic(r.mesh), 0);
  EXPECT_GT(signed_volume(r.mesh), 0);
  for (size_t v = 0; v < 16; ++v) EXPECT_EQ(r.mesh.mean(v), twice.mesh.mean(v)) << v;  // kept in order
  EXPECT_EQ(r.selection, once.selection);
}

TEST(Bridge, FaceAndCoincidenceRefusals) {
  const CovarianceMesh cube = test::cube_mesh();
  const std::string joined = error_of([&] { bridge_faces(cube, {0, 1}); });
  EXPECT_NE(joined.find("already joins the loops: the bridge would give it a third face"), std::string::npos) << joined;
  EXPECT_EQ(error_of([&] { bridge_faces(cube, {0}); }),
            "the faces make 1 region (faces joined by edges); bridge needs exactly 2");
  EXPECT_EQ(error_of([&] {
              bridge_faces(cube, {0, 2, 1});
            }),
            "the faces make 1 region (faces joined by edges); bridge needs exactly 2");
  EXPECT_EQ(error_of([&] { bridge_faces(cube, {0, 6}); }), "face 6 is not in the mesh (6 faces)");
  const CovarianceMesh grid = test::grid_mesh(4, 4);
  EXPECT_EQ(error_of([&] { bridge_faces(grid, {5, 10}); }), "the regions of faces 5 and 10 touch at vertex 12");
  EXPECT_EQ(error_of([&] {
              bridge_faces(grid, {0, 10});
            }),
            "the region of face 0 reaches the mesh's boundary at edge 0–1 and meets other faces too: their borders "
            "cannot both be bridged");
  // Two quads on the same four points, facing apart: every face of a bridge would be flat.
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  std::vector<Vec3> twice = p;
  twice.insert(twice.end(), p.begin(), p.end());
  const CovarianceMesh caps =
      make_covariance_mesh(twice, std::vector<Mat3>(8, 0.1 * Mat3::Identity()), {{0, 1, 2, 3}, {4, 7, 6, 5}});
  const std::string flat = error_of([&] { bridge(caps, {0, 1, 2, 3}, {4, 5, 6, 7}); });
  EXPECT_NE(flat.find("would have no area (the loops coincide or line up there)"), std::string::npos) << flat;
  EXPECT_EQ(error_of([] { OperationList::parse(R"([{"op":"bridge","faces":[0],"loops":[[0],[1]]}])", "ops.json"); }),
            "ops.json: ops[0] (bridge): give one of \"loops\" or \"faces\"");
  EXPECT_EQ(cube.n_faces(), 6u);
}

// Two faces apart (a cube's top and bottom alone): their borders are the mesh's boundary; as in
// Blender they are bridged and the faces go, leaving an open tube.
TEST(Bridge, TwoFacesApartLeaveTheBandBetweenThem) {
  const MeshArrays cube = arrays_of(test::cube_mesh());
  const CovarianceMesh caps = make_covariance_mesh(cube.means, cube.covariances, {cube.faces[0], cube.faces[1]});
  const Modelled r = bridge_faces(caps, {0, 1});
  EXPECT_EQ(r.mesh.n_vertices(), 8u);
  EXPECT_EQ(r.mesh.n_faces(), 4u);
  const SurfaceCounts counts = surface_counts(r.mesh.topology(), r.mesh.connectivity());
  EXPECT_EQ(counts.parts, 1);
  EXPECT_EQ(counts.boundary_loops, 2);
  EXPECT_EQ(r.selection, range(0, 8));
  EXPECT_EQ(r.summary, "deleted 2 faces, bridged two loops of 4 vertices: 4 faces added");
  // The band faces out, as the cube's sides do.
  for (size_t f = 0; f < r.mesh.n_faces(); ++f) {
    Vec3 normal = Vec3::Zero(), centre = Vec3::Zero();
    const std::span<const int> c = r.mesh.face(f);
    for (size_t k = 0; k < c.size(); ++k) {
      normal += r.mesh.mean(size_t(c[k])).cross(r.mesh.mean(size_t(c[(k + 1) % c.size()])));
      centre += r.mesh.mean(size_t(c[k])) / double(c.size());
    }
    EXPECT_GT(normal.dot(centre), 0) << f;
  }
}

}  // namespace
}  // namespace gps
