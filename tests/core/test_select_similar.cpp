// Select similar (core/modelling/select_similar.h) on the cube, a bevelled cube and a grid.
#include "core/modelling/select_similar.h"

#include <gtest/gtest.h>

#include "core/modelling/bevel.h"
#include "core/modelling/samples.h"
#include "tests/support/error_of.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

TEST(SelectSimilar, EdgesOfTheSameLengthOrCrease) {
  const CovarianceMesh cube = make_sample("cube");
  EXPECT_EQ(similar_edges(cube, {{6, 7}}, Similarity::edge_length, 0.0).size(), 12u);  // every edge is 2 long
  EXPECT_TRUE(similar_edges(cube, {}, Similarity::edge_length, 0.0).empty());
  // The band a bevel of width 0.25 makes: its ends are shorter than 2, its sides (the cut edge's
  // copies) and the edges it did not touch are 2 long; a tolerance of 50 % takes the ends too.
  BevelOptions o;
  o.width = 0.25;
  const CovarianceMesh bevelled = bevel_edges(cube, {{6, 7}}, o).mesh;
  const size_t edges = bevelled.n_edges();
  const auto two_long = similar_edges(bevelled, {{0, 1}}, Similarity::edge_length, 0.0);
  EXPECT_LT(two_long.size(), edges);
  EXPECT_GE(two_long.size(), 8u);
  EXPECT_EQ(similar_edges(bevelled, {{0, 1}}, Similarity::edge_length, 0.9).size(), edges);
  CovarianceMesh creased = cube;
  creased.sharpness.set_crease(6, 7, 2.0);
  creased.sharpness.set_crease(0, 1, 2.0);
  creased.sharpness.set_crease(1, 2, 3.0);
  EXPECT_EQ(similar_edges(creased, {{6, 7}}, Similarity::edge_crease, 0.0),
            (std::vector<std::array<int, 2>>{{0, 1}, {6, 7}}));
  EXPECT_EQ(similar_edges(creased, {{6, 7}}, Similarity::edge_crease, 1.0).size(), 3u);
  EXPECT_NE(test::error_of([&] { similar_edges(cube, {{6, 7}}, Similarity::face_area, 0.0); }), "");
}

TEST(SelectSimilar, FacesByAreaSidesAndNormal) {
  const CovarianceMesh grid = test::grid_mesh(4, 4);  // bumpy: no two normals alike, areas near 1
  EXPECT_EQ(similar_faces(grid, {0}, Similarity::face_sides, 0.0).size(), 16u);
  EXPECT_EQ(similar_faces(grid, {0}, Similarity::face_normal, 0.0), (std::vector<int>{0}));
  EXPECT_EQ(similar_faces(grid, {0}, Similarity::face_normal, 1.0).size(), 16u);  // within 180°
  EXPECT_EQ(similar_faces(grid, {0}, Similarity::face_area, 0.0), (std::vector<int>{0}));
  const CovarianceMesh cube = make_sample("cube");
  EXPECT_EQ(similar_faces(cube, {0}, Similarity::face_area, 0.0).size(), 6u);
  // A normal within 90° + ε takes the face and its four neighbours, not the opposite one.
  EXPECT_EQ(similar_faces(cube, {0}, Similarity::face_normal, 0.51).size(), 5u);
}

TEST(SelectSimilar, VerticesWithAsManyEdges) {
  const CovarianceMesh grid = test::grid_mesh(4, 4);
  EXPECT_EQ(similar_vertices(grid, {0}, Similarity::vertex_edges), (std::vector<int>{0, 4, 20, 24}));  // corners
  EXPECT_EQ(similar_vertices(grid, {12}, Similarity::vertex_edges).size(), 9u);                        // inside
  EXPECT_EQ(similar_vertices(grid, {1}, Similarity::vertex_edges).size(), 12u);                        // sides
}

}  // namespace
}  // namespace gps
