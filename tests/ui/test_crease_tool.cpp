// The crease tool's values: a drag's span covering smooth to ∞, rounded to tenths and clamped; the
// text and colour of a sharpness; "mixed" selections; the mirror images of edges and vertices; the
// selection's edges, not the edges between their ends.
#include "ui/editing/crease_tool.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/modelling/samples.h"
#include "core/mesh/sharpness.h"

namespace gps {
namespace {

TEST(CreaseTool, ADragOfTheSpanGoesFromSmoothToInfinitelySharp) {
  const float width = 1000.0f, span = crease_drag_span(width);
  EXPECT_GT(span, 0.1f * width);
  EXPECT_LT(span, width);
  EXPECT_EQ(sharpness_after_drag(0.0, span, width), kInfiniteSharpness);
  EXPECT_EQ(sharpness_after_drag(0.0, 0.5f * span, width), 5.0);
  EXPECT_EQ(sharpness_after_drag(4.0, -0.1f * span, width), 3.0);
  EXPECT_EQ(sharpness_after_drag(0.0, 0.123f * span, width), 1.2);  // tenths
  EXPECT_EQ(sharpness_after_drag(2.0, -span, width), 0.0);          // clamped
  EXPECT_EQ(sharpness_after_drag(9.0, span, width), kInfiniteSharpness);
  EXPECT_GT(crease_drag_span(10.0f), 10.0f);  // a tiny window still needs a real drag
}

TEST(CreaseTool, TextShowsInfinityFromTen) {
  EXPECT_EQ(sharpness_text(0.0), "0.00");
  EXPECT_EQ(sharpness_text(2.5), "2.50");
  EXPECT_EQ(sharpness_text(9.99), "9.99");
  EXPECT_EQ(sharpness_text(kInfiniteSharpness), "∞");
  EXPECT_EQ(sharpness_text(42.0), "∞");
}

TEST(CreaseTool, ColourGoesFromGreyToMagenta) {
  const auto smooth = crease_colour(0.0), half = crease_colour(5.0), sharp = crease_colour(kInfiniteSharpness);
  EXPECT_EQ(smooth[0], smooth[1]);  // grey
  EXPECT_EQ(smooth[1], smooth[2]);
  EXPECT_GT(sharp[0], 0.9f);  // magenta: red and blue, little green
  EXPECT_GT(sharp[2], 0.7f);
  EXPECT_LT(sharp[1], 0.2f);
  EXPECT_GT(half[0], smooth[0]);
  EXPECT_LT(half[0], sharp[0]);
  EXPECT_EQ(crease_colour(20.0), sharp);
}

TEST(CreaseTool, CommonValuesOrMixed) {
  CovarianceMesh cube = make_sample("cube");
  EXPECT_EQ(common_crease(cube, {{2, 3}, {3, 7}}), 0.0);
  cube.sharpness.set_crease(2, 3, 2.0);
  cube.sharpness.set_crease(7, 3, 2.0);
  EXPECT_EQ(common_crease(cube, {{2, 3}, {3, 7}}), 2.0);
  EXPECT_TRUE(std::isnan(common_crease(cube, {{2, 3}, {6, 7}})));
  EXPECT_EQ(common_corner(cube, {0, 1}), 0.0);
  cube.sharpness.set_corner(1, 3.0, int(cube.n_vertices()));
  EXPECT_TRUE(std::isnan(common_corner(cube, {0, 1})));
  EXPECT_EQ(common_corner(cube, {1}), 3.0);
}

// The cube's corners at x = ±1: 0 ↔ 1, 3 ↔ 2, 4 ↔ 5, 7 ↔ 6 across x = 0.
TEST(CreaseTool, MirrorEditingTakesTheMirroredEdgesAndVertices) {
  const CovarianceMesh cube = make_sample("cube");
  ReachOptions reach;
  using Edges = std::vector<std::array<int, 2>>;
  EXPECT_EQ(with_mirrored_edges(cube, {{3, 0}}, reach), (Edges{{0, 3}}));
  reach.mirror = true;
  reach.mirror_axis = 0;
  EXPECT_EQ(with_mirrored_edges(cube, {{3, 0}}, reach), (Edges{{0, 3}, {1, 2}}));
  EXPECT_EQ(with_mirrored_edges(cube, {{3, 2}}, reach), (Edges{{2, 3}}));  // its own mirror image
  EXPECT_EQ(with_mirrored_edges(cube, {{0, 3}, {1, 2}}, reach), (Edges{{0, 3}, {1, 2}}));
  EXPECT_EQ(with_mirrored_vertices(cube, {4}, reach), (std::vector<int>{4, 5}));
  reach.mirror_axis = 1;  // across y = 0: 0 ↔ 3
  EXPECT_EQ(with_mirrored_vertices(cube, {0}, reach), (std::vector<int>{0, 3}));
  reach.mirror = false;
  EXPECT_EQ(with_mirrored_vertices(cube, {4}, reach), (std::vector<int>{4}));
}

// The crease takes the selection's edges: in edge mode the edges picked, not the edges between
// their ends (two opposite edges of a cube's face crease, the face's other two sides stay smooth).
TEST(CreaseTool, SharpensTheSelectedEdgesOnly) {
  const CovarianceMesh cube = make_sample("cube");  // face {0, 1, 5, 4}
  Selection edges;
  edges.select_edges(cube, {{0, 1}, {4, 5}}, false);
  const Modelled creased = sharpened_selection(cube, edges, false, 3.0, ReachOptions{});
  ASSERT_EQ(creased.mesh.sharpness.creases.size(), 2u);
  EXPECT_EQ(creased.mesh.sharpness.crease(0, 1), 3.0);
  EXPECT_EQ(creased.mesh.sharpness.crease(4, 5), 3.0);
  EXPECT_EQ(creased.mesh.sharpness.crease(0, 4), 0.0);
  Selection vertices;  // the same four vertices as vertices: all four sides of the face
  vertices.select({0, 1, 4, 5}, false);
  EXPECT_EQ(sharpened_selection(cube, vertices, false, 3.0, ReachOptions{}).mesh.sharpness.creases.size(), 4u);
  const Sharpness corners = sharpened_selection(cube, edges, true, 2.0, ReachOptions{}).mesh.sharpness;
  for (int v = 0; v < 8; ++v) EXPECT_EQ(corners.corner(v), v == 0 || v == 1 || v == 4 || v == 5 ? 2.0 : 0.0) << v;
}

}  // namespace
}  // namespace gps
