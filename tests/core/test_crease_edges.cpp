// Creases and corners as modelling operations (core/modelling/crease_edges.h), and the other
// operations keeping them: through renumbering, merges and split edges.
#include <gtest/gtest.h>

#include "core/support/error.h"
#include "core/modelling/samples.h"
#include "core/modelling/crease_edges.h"
#include "core/modelling/delete_elements.h"
#include "core/modelling/edge_operations.h"
#include "core/modelling/loop_cut.h"
#include "core/modelling/merge_vertices.h"
#include "core/modelling/subdivide_mesh.h"
#include "tests/support/error_of.h"

namespace gps {
namespace {

using test::error_of;

// Every crease of the mesh lies on one of its edges.
void expect_creases_on_edges(const CovarianceMesh& m) {
  for (const EdgeCrease& c : m.sharpness.creases) {
    EXPECT_GE(m.find_edge(c.a, c.b), 0) << "crease " << c.a << "-" << c.b;
  }
}

// The sample cube (top face 4 5 6 7) with its top edges infinitely sharp.
CovarianceMesh creased_cube() {
  return set_crease(make_sample("cube"), {{4, 5}, {5, 6}, {6, 7}, {7, 4}}, kInfiniteSharpness).mesh;
}

TEST(CreaseEdges, SetsCreasesLeavingTheMeshAsItIs) {
  const CovarianceMesh cube = make_sample("cube");
  const Modelled m = set_crease(cube, {{4, 5}, {6, 5}, {6, 7}, {7, 4}}, kInfiniteSharpness);
  Sharpness expected;
  expected.creases = {{4, 5, 10.0}, {4, 7, 10.0}, {5, 6, 10.0}, {6, 7, 10.0}};
  EXPECT_EQ(m.mesh.sharpness, expected);
  EXPECT_EQ(m.selection, (std::vector<int>{4, 5, 6, 7}));
  EXPECT_EQ(m.summary, "set the crease of 4 edges to 10 (infinitely sharp)");
  ASSERT_EQ(m.mesh.n_vertices(), cube.n_vertices());
  for (size_t v = 0; v < cube.n_vertices(); ++v) {
    EXPECT_EQ(m.mesh.mean(v), cube.mean(v));
    EXPECT_EQ(m.mesh.covariance(v), cube.covariance(v));
  }
  // 0 makes them smooth again.
  const Modelled smooth = set_crease(m.mesh, {{4, 5}, {5, 6}, {6, 7}, {7, 4}}, 0.0);
  EXPECT_TRUE(smooth.mesh.sharpness.empty());
  EXPECT_EQ(smooth.summary, "set the crease of 4 edges to 0 (smooth)");
  // An edge listed twice, either way round, is one edge.
  EXPECT_EQ(set_crease(cube, {{0, 1}, {1, 0}, {0, 1}}, 1.0).summary, "set the crease of 1 edge to 1");
}

TEST(CreaseEdges, SetsAndRemovesCorners) {
  const Modelled m = set_corner(make_sample("cube"), {3, 0, 3}, 2.5);
  EXPECT_EQ(m.mesh.sharpness.corners, (std::vector<double>{2.5, 0, 0, 2.5, 0, 0, 0, 0}));
  EXPECT_EQ(m.selection, (std::vector<int>{0, 3}));
  EXPECT_EQ(m.summary, "set the corner of 2 vertices to 2.5");
  EXPECT_TRUE(set_corner(m.mesh, {0, 3}, 0.0).mesh.sharpness.empty());
}

TEST(CreaseEdges, RefusalsNameTheElement) {
  const CovarianceMesh cube = make_sample("cube");
  EXPECT_EQ(error_of([&] { set_crease(cube, {{4, 5}}, -1.0); }), "sharpness -1 is negative");
  EXPECT_EQ(error_of([&] { set_corner(cube, {4}, std::nan("")); }), "sharpness nan is not finite");
  EXPECT_EQ(error_of([&] { set_crease(cube, {{4, 5}, {0, 6}}, 1.0); }), "edge 0–6 is not in the mesh");
  EXPECT_EQ(error_of([&] { set_crease(cube, {{4, 4}}, 1.0); }), "edge 4–4 is not in the mesh");
  EXPECT_EQ(error_of([&] { set_crease(cube, {{4, 9}}, 1.0); }), "vertex 9 is not in the mesh (8 vertices)");
  EXPECT_EQ(error_of([&] { set_corner(cube, {8}, 1.0); }), "vertex 8 is not in the mesh (8 vertices)");
}

TEST(CreaseEdges, DeletionRenumbersCreasesAndCorners) {
  CovarianceMesh cube = creased_cube();
  cube.sharpness.set_corner(6, 3.0, 8);
  cube.sharpness.set_corner(0, 1.0, 8);
  const Modelled m = delete_vertices(cube, {0});  // vertices 1..7 become 0..6
  Sharpness expected;
  expected.creases = {{3, 4, 10.0}, {3, 6, 10.0}, {4, 5, 10.0}, {5, 6, 10.0}};
  expected.corners = {0, 0, 0, 0, 0, 3.0, 0};
  EXPECT_EQ(m.mesh.sharpness, expected);
  expect_creases_on_edges(m.mesh);
}

TEST(CreaseEdges, SplittingACreasedEdgeCreasesBothHalves) {
  CovarianceMesh cube = set_crease(make_sample("cube"), {{4, 5}}, 2.5).mesh;
  const Modelled split = split_edge(cube, 4, 5);
  ASSERT_EQ(split.selection, (std::vector<int>{8}));
  Sharpness expected;
  expected.creases = {{4, 8, 2.5}, {5, 8, 2.5}};
  EXPECT_EQ(split.mesh.sharpness, expected);
  expect_creases_on_edges(split.mesh);

  // A loop cut across the ring through 4–5 cuts it and its opposite edges; 4–5's pieces stay creased.
  const Modelled cut = loop_cut(cube, 4, 5, 2);
  int pieces = 0;
  for (const EdgeCrease& c : cut.mesh.sharpness.creases) {
    EXPECT_EQ(c.sharpness, 2.5);
    pieces += 1;
  }
  EXPECT_EQ(pieces, 3);
  expect_creases_on_edges(cut.mesh);
  EXPECT_EQ(cut.mesh.sharpness.crease(4, 5), 0.0);
}

TEST(CreaseEdges, SubdividingFacesCreasesBothHalvesOfTheirCreasedEdges) {
  const Modelled m = subdivide_faces(creased_cube(), {1});  // the top face 4 5 6 7
  EXPECT_EQ(m.mesh.sharpness.creases.size(), 8u);
  for (const EdgeCrease& c : m.mesh.sharpness.creases) {
    EXPECT_EQ(c.sharpness, kInfiniteSharpness);
    EXPECT_TRUE(c.a >= 4 && c.a < 8) << c.a << "-" << c.b;  // each half has one of the old top corners
    EXPECT_GE(c.b, 8);
  }
  expect_creases_on_edges(m.mesh);
}

TEST(CreaseEdges, MergingDropsCollapsedCreasesAndKeepsTheOthers) {
  const Modelled m = merge_vertices(creased_cube(), {4, 5}, MergePoint::center);
  // 4 and 5 become one vertex (4); 5..7 become 5..6 after it: 4–5 is gone, the other three stay.
  EXPECT_EQ(m.mesh.sharpness.creases.size(), 3u);
  expect_creases_on_edges(m.mesh);
}

}  // namespace
}  // namespace gps
