#include "core/modelling/bridge.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/support/error.h"
#include "core/modelling/samples.h"
#include "core/modelling/mesh_queries.h"
#include "tests/support/error_of.h"

namespace gps {
namespace {

using test::error_of;
using V = std::vector<int>;

int boundary_edges_of_oriented(const CovarianceMesh& m) {
  const MeshArrays a = arrays_of(m);
  const DirectedEdges edges = directed_edges(a);
  size_t corners = 0;
  for (const auto& face : a.faces) corners += face.size();
  EXPECT_EQ(edges.size(), corners) << "a directed edge is used twice";
  int boundary = 0;
  for (const auto& [key, where] : edges) boundary += edges.count((key << 32) | (key >> 32)) == 0;
  return boundary;
}

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
  EXPECT_EQ(error_of([&] { bridge(cut, ring(0), eight); }), "loops of 12 and 8 vertices: bridge needs equal lengths");
  EXPECT_EQ(error_of([&] { bridge(cut, ring(0), ring(0)); }), "vertex 0 is in both loops");
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
            "loops of 12 and 2 vertices: bridge needs equal lengths");
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

}  // namespace
}  // namespace gps
