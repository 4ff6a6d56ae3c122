// Edge and vertex slides (core/modelling/slide.h): a cube's loop-cut loop slid by ±1 lands on the
// loops beside it, a slide after a cut is the cut at the slid parameter (9D blends), even slides
// move every vertex the same distance, factor 0 is the identity, the topology never changes, and
// refusals name the element.
#include "core/modelling/slide.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/modelling/loop_cut.h"
#include "core/modelling/operation_list.h"
#include "tests/support/error_of.h"
#include "tests/support/test_meshes.h"
#include "tests/support/mesh_checks.h"

namespace gps {
namespace {

using test::expect_same_arrays;

using test::error_of;
using Edges = std::vector<std::array<int, 2>>;

// The cube cut once across the ring through edge 0–1 (x from −1 to 1): vertices 8..11 at x = 0.
CovarianceMesh cut_cube() { return loop_cut(test::cube_mesh(), 0, 1).mesh; }

// The edges of the mesh between two of `vertices`, each listed once (as the faces first run it).
Edges edges_among(const CovarianceMesh& m, const std::vector<int>& vertices) {
  const auto in = [&](int v) { return std::find(vertices.begin(), vertices.end(), v) != vertices.end(); };
  Edges out;
  for (const auto& f : arrays_of(m).faces)
    for (size_t k = 0; k < f.size(); ++k) {
      const int a = f[k], b = f[(k + 1) % f.size()];
      if (in(a) && in(b) && a < b) out.push_back({a, b});
    }
  return out;
}

TEST(EdgeSlide, TheCubesCutLoopLandsOnTheLoopsBesideIt) {
  const CovarianceMesh cut = cut_cube();
  const MeshArrays before = arrays_of(cut);
  const std::vector<int> loop = {8, 9, 10, 11};
  const Edges edges = edges_among(cut, loop);
  ASSERT_EQ(edges.size(), 4u);
  std::vector<double> side_x;
  for (const double factor : {1.0, -1.0}) {
    const Modelled r = edge_slide(cut, edges, factor);
    const MeshArrays after = arrays_of(r.mesh);
    EXPECT_EQ(after.faces, before.faces);
    EXPECT_EQ(r.selection, loop);
    const double x = after.means[8].x();
    EXPECT_EQ(std::abs(x), 1.0);
    side_x.push_back(x);
    for (int v : loop) {
      // Exactly on one of the cube's own corners on that side, Gaussian and all.
      int landed = -1;
      for (int c = 0; c < 8; ++c)
        if (after.means[size_t(v)] == before.means[size_t(c)]) landed = c;
      ASSERT_GE(landed, 0) << "vertex " << v;
      EXPECT_EQ(before.means[size_t(landed)].x(), x);
      EXPECT_EQ(after.covariances[size_t(v)], before.covariances[size_t(landed)]);
    }
    for (int v = 0; v < 8; ++v) EXPECT_EQ(after.means[size_t(v)], before.means[size_t(v)]);
  }
  EXPECT_EQ(side_x[0], -side_x[1]);  // the two signs pick the two sides
  EXPECT_EQ(edge_slide(cut, edges, 0.5).summary, "slid 4 vertices of 4 edges by 0.5");
}

TEST(EdgeSlide, FactorZeroIsTheIdentity) {
  const CovarianceMesh cut = cut_cube();
  const Modelled r = edge_slide(cut, edges_among(cut, {8, 9, 10, 11}), 0.0, true);
  expect_same_arrays(arrays_of(r.mesh), arrays_of(cut));
  expect_same_arrays(arrays_of(vertex_slide(cut, 8, 0, 0.0).mesh), arrays_of(cut));
}

TEST(EdgeSlide, ASlideAfterACutIsTheCutAtTheSlidParameter) {
  // Every vertex its own covariance: the new Gaussians are 9D blends, not averages of the means.
  MeshArrays cube = arrays_of(test::cube_mesh());
  for (int v = 0; v < 8; ++v) {
    const Vec3 d(0.02 + 0.01 * v, 0.05 + 0.003 * v * v, 0.09 - 0.008 * v);
    cube.covariances[size_t(v)] = d.asDiagonal();
    cube.covariances[size_t(v)](0, 1) = cube.covariances[size_t(v)](1, 0) = 0.004 * (v % 3);
  }
  const CovarianceMesh mesh = build_mesh(cube);
  const CovarianceMesh cut = loop_cut(mesh, 0, 1).mesh;
  const Edges edges = edges_among(cut, {8, 9, 10, 11});
  for (const double factor : {0.6, -0.3}) {
    const MeshArrays slid = arrays_of(edge_slide(cut, edges, factor).mesh);
    // The side the factor picked: where vertex 8 went, and the cut slid toward it by as much.
    const double toward = slid.means[8].x() > 0 ? 1.0 : -1.0;
    const MeshArrays direct = arrays_of(loop_cut(mesh, 0, 1, 1, toward * std::abs(factor)).mesh);
    EXPECT_EQ(slid.faces, direct.faces);
    for (size_t v = 8; v < 12; ++v) {
      EXPECT_LT((slid.means[v] - direct.means[v]).norm(), 1e-12) << v;
      EXPECT_LT((slid.covariances[v] - direct.covariances[v]).norm(), 1e-12) << v;
    }
  }
}

TEST(EdgeSlide, EvenMovesEveryVertexTheSameDistance) {
  // The middle row of a 4 × 2 grid (vertices 5..9), the row above it raised unevenly: its edges up
  // there differ in length.
  MeshArrays raised = arrays_of(test::grid_mesh(4, 2));
  for (int i = 0; i <= 4; ++i) raised.means[size_t(10 + i)].z() += 0.4 * i;
  const CovarianceMesh grid = build_mesh(raised);
  const MeshArrays before = arrays_of(grid);
  const Edges row = {{5, 6}, {6, 7}, {7, 8}, {8, 9}};
  double shortest = INFINITY, longest = 0;
  for (int v = 5; v <= 9; ++v) {
    const double l = (before.means[size_t(v + 5)] - before.means[size_t(v)]).norm();  // up to row 2
    shortest = std::min(shortest, l);
    longest = std::max(longest, l);
  }
  ASSERT_GT(longest - shortest, 0.1);
  const MeshArrays even = arrays_of(edge_slide(grid, row, 0.5, true).mesh);
  const MeshArrays plain = arrays_of(edge_slide(grid, row, 0.5).mesh);
  for (int v = 5; v <= 9; ++v) {
    const Vec3 up = before.means[size_t(v + 5)] - before.means[size_t(v)];
    const Vec3 moved = even.means[size_t(v)] - before.means[size_t(v)];
    EXPECT_NEAR(moved.norm(), 0.5 * shortest, 1e-12) << v;
    EXPECT_LT(moved.cross(up).norm(), 1e-12) << v;  // along its own edge up
    EXPECT_GT(moved.dot(up), 0) << v;
    EXPECT_LT((plain.means[size_t(v)] - (before.means[size_t(v)] + 0.5 * up)).norm(), 1e-12) << v;
  }
}

TEST(VertexSlide, MovesAlongTheChosenEdge) {
  const CovarianceMesh cube = test::cube_mesh();
  const Modelled quarter = vertex_slide(cube, 0, 1, 0.25);
  EXPECT_LT((quarter.mesh.mean(0) - Vec3(-0.5, -1, -1)).norm(), 1e-12);
  EXPECT_EQ(quarter.selection, std::vector<int>{0});
  EXPECT_EQ(quarter.summary, "slid vertex 0 0.25 of the way along edge 0–1");
  EXPECT_EQ(arrays_of(quarter.mesh).faces, arrays_of(cube).faces);
  for (size_t v = 1; v < 8; ++v) EXPECT_EQ(quarter.mesh.mean(v), cube.mean(v));
  const Modelled whole = vertex_slide(cube, 0, 4, 1.0);
  EXPECT_EQ(whole.mesh.mean(0), cube.mean(4));
  EXPECT_EQ(whole.mesh.covariance(0), cube.covariance(4));
}

TEST(Slide, RefusalsNameTheElement) {
  const CovarianceMesh cube = test::cube_mesh();
  const CovarianceMesh cut = cut_cube();
  const Edges loop = edges_among(cut, {8, 9, 10, 11});
  EXPECT_EQ(error_of([&] { edge_slide(cut, loop, 1.5); }), "the slide factor must be in [-1, 1], got 1.5");
  EXPECT_EQ(error_of([&] { edge_slide(cube, {{0, 6}}, 0.5); }), "edge 0–6 is not in the mesh");
  EXPECT_EQ(error_of([&] { edge_slide(cube, {{0, 9}}, 0.5); }), "vertex 9 is not in the mesh (8 vertices)");
  EXPECT_EQ(error_of([&] { edge_slide(cube, {}, 0.5); }), "no edges to slide");
  EXPECT_EQ(error_of([&] {
              edge_slide(cube, {{0, 1}, {0, 3}, {0, 4}}, 0.5);
            }),
            "vertex 0 is on 3 selected edges: slide needs loops or chains");
  // Around the cube's corner 1: the third edge there on one side, the face the chain bends round on
  // the other.
  EXPECT_NO_THROW(edge_slide(cube, {{0, 1}, {1, 2}}, 0.5));
  EXPECT_EQ(error_of([&] {
              edge_slide(cube, {{0, 1}, {1, 2}}, -0.5);
            }),
            "vertex 1 has no edge leaving the selection on the side the factor picks (a boundary there)");
  // The grid's bottom row: faces above it only.
  const CovarianceMesh grid = test::grid_mesh(4, 2);
  EXPECT_NO_THROW(edge_slide(grid, {{0, 1}, {1, 2}}, 1.0));
  EXPECT_EQ(error_of([&] {
              edge_slide(grid, {{0, 1}, {1, 2}}, -1.0);
            }),
            "vertex 0 has no edge leaving the selection on the side the factor picks (a boundary there)");
  // Two neighbours of a valence-5 vertex of the icosahedron, one apart around it: one edge leaves
  // on one side, two on the other.
  const CovarianceMesh ico = test::icosahedron_mesh();
  std::vector<int> around;  // the neighbours of vertex 0 in order around it
  {
    const MeshArrays a = arrays_of(ico);
    std::map<int, int> next;
    for (const auto& f : a.faces)
      for (size_t k = 0; k < 3; ++k)
        if (f[k] == 0) next[f[(k + 1) % 3]] = f[(k + 2) % 3];
    for (int v = next.begin()->first; around.size() < next.size(); v = next[v]) around.push_back(v);
  }
  ASSERT_EQ(around.size(), 5u);
  const Edges bend = {{around[0], 0}, {0, around[2]}};
  const std::string plus = error_of([&] { edge_slide(ico, bend, 0.5); });
  const std::string minus = error_of([&] { edge_slide(ico, bend, -0.5); });
  EXPECT_TRUE((plus == "(accepted)") != (minus == "(accepted)")) << plus << " / " << minus;
  EXPECT_NE((plus + minus).find("vertex 0 has 2 edges leaving the selection"), std::string::npos) << plus << minus;
  EXPECT_EQ(error_of([&] { vertex_slide(cube, 0, 6, 0.5); }), "edge 0–6 is not in the mesh");
  EXPECT_EQ(error_of([&] { vertex_slide(cube, 0, 1, -0.5); }), "the slide factor must be in [0, 1], got -0.5");
  EXPECT_EQ(error_of([&] { vertex_slide(cube, 0, 0, 0.5); }), "edge 0–0 is not in the mesh");
}

TEST(Slide, AsOperationsInAList) {
  const CovarianceMesh cut = cut_cube();
  const Edges loop = edges_among(cut, {8, 9, 10, 11});
  std::string edges_json;
  for (const auto& [a, b] : loop)
    edges_json += std::string(edges_json.empty() ? "" : ",") + "[" + std::to_string(a) + "," + std::to_string(b) + "]";
  const OperationList list =
      OperationList::parse("[{\"op\":\"slide\",\"edges\":[" + edges_json + "],\"factor\":0.4,\"even\":true}," +
                               "{\"op\":\"slide\",\"vertex\":0,\"toward\":3,\"factor\":0.5}]",
                           "ops.json");
  const Modelled r = list.apply(cut);
  const Modelled direct = vertex_slide(edge_slide(cut, loop, 0.4, true).mesh, 0, 3, 0.5);
  expect_same_arrays(arrays_of(r.mesh), arrays_of(direct.mesh));
  EXPECT_EQ(
      error_of([] { OperationList::parse(R"([{"op":"slide","edges":[[0,1]],"factor":0.4,"even":1}])", "ops.json"); }),
      "ops.json: ops[0] (slide): \"even\" must be true or false");
  EXPECT_EQ(error_of([] { OperationList::parse(R"([{"op":"slide","vertex":0,"factor":0.4}])", "ops.json"); }),
            "ops.json: ops[0] (slide): \"toward\" is missing");
  EXPECT_EQ(error_of([] { OperationList::parse(R"([{"op":"slide","factor":0.4}])", "ops.json"); }),
            "ops.json: ops[0] (slide): give \"edges\" or \"vertex\"");
  EXPECT_EQ(error_of([&] {
              OperationList::parse(R"([{"op":"slide","vertex":0,"toward":6,"factor":0.4}])", "ops.json").apply(cut);
            }),
            "ops.json: ops[0] (slide): edge 0–6 is not in the mesh");
}

}  // namespace
}  // namespace gps
