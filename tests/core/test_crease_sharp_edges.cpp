// Creasing the edges sharper than an angle (core/modelling/crease_edges.h, crease_sharp_edges): the
// cube's 12 edges at 30°, none of the icosahedron's 41.8° folds at 45° and all 30 at 40°, boundary
// edges never, the Gaussians untouched, refusals, and the op list's {"edges": "sharp"}.
#include <gtest/gtest.h>

#include "core/modelling/crease_edges.h"
#include "core/modelling/operation_list.h"
#include "core/modelling/samples.h"
#include "tests/support/error_of.h"
#include "tests/support/mesh_checks.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

using test::error_of;

TEST(CreaseSharpEdges, TheCubesTwelveEdgesAtThirtyDegrees) {
  const CovarianceMesh cube = test::with_random_covariances(make_sample("cube"), 4);
  const Modelled r = crease_sharp_edges(cube, 30, 2.5);
  ASSERT_EQ(r.mesh.sharpness.creases.size(), 12u);
  for (const EdgeCrease& c : r.mesh.sharpness.creases) EXPECT_EQ(c.sharpness, 2.5);
  EXPECT_EQ(r.selection, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(r.summary, "set the crease of 12 edges sharper than 30° to 2.5");
  // The Gaussians and faces stay as they are: only the sharpness changes.
  CovarianceMesh uncreased = r.mesh;
  uncreased.sharpness = cube.sharpness;
  EXPECT_TRUE(test::same_mesh(uncreased, cube));
  EXPECT_TRUE(cube.sharpness.empty());
}

// The icosahedron's faces meet at 41.81° between their normals (180° less its dihedral angle).
TEST(CreaseSharpEdges, OnlyEdgesPastTheAngle) {
  const CovarianceMesh ico = test::icosahedron_mesh();
  EXPECT_EQ(crease_sharp_edges(ico, 40, kInfiniteSharpness).mesh.sharpness.creases.size(), 30u);
  const Modelled none = crease_sharp_edges(ico, 45, kInfiniteSharpness);
  EXPECT_TRUE(none.mesh.sharpness.empty());
  EXPECT_TRUE(none.selection.empty());
  EXPECT_EQ(none.summary, "set the crease of 0 edges sharper than 45° to 10 (infinitely sharp)");
  // An open grid folded by its bump: boundary edges have one face, no angle, and are never creased.
  const CovarianceMesh grid = test::grid_mesh(4, 3);
  const Modelled all = crease_sharp_edges(grid, 0, 1);
  const MeshArrays a = arrays_of(grid);
  const DirectedEdges edges = directed_edges(a);
  for (const EdgeCrease& c : all.mesh.sharpness.creases) EXPECT_FALSE(is_boundary_edge(edges, c.a, c.b));
  EXPECT_GT(all.mesh.sharpness.creases.size(), 0u);
}

TEST(CreaseSharpEdges, RefusalsSayWhy) {
  const CovarianceMesh cube = make_sample("cube");
  EXPECT_EQ(error_of([&] { crease_sharp_edges(cube, 180, 1); }),
            "the angle must be from 0 to less than 180 degrees, got 180");
  EXPECT_EQ(error_of([&] { crease_sharp_edges(cube, -1, 1); }),
            "the angle must be from 0 to less than 180 degrees, got -1");
  EXPECT_EQ(error_of([&] { crease_sharp_edges(cube, 30, -2); }), "sharpness -2 is negative");
}

TEST(CreaseSharpEdges, TheOperationList) {
  const CovarianceMesh cube = make_sample("cube");
  const Modelled scripted =
      OperationList::parse(R"([{"op":"crease","edges":"sharp","angle":30,"sharpness":3}])", "o").apply(cube);
  EXPECT_EQ(scripted.mesh.sharpness, crease_sharp_edges(cube, 30, 3).mesh.sharpness);
  EXPECT_EQ(scripted.mesh.sharpness.creases.size(), 12u);
  const auto parse_error = [](const std::string& text) { return error_of([&] { OperationList::parse(text, "o"); }); };
  EXPECT_EQ(parse_error(R"([{"op":"crease","edges":"soft","angle":30,"sharpness":3}])"),
            "o: ops[0] (crease): \"edges\" must be \"sharp\" or a list of [a, b] edges");
  EXPECT_EQ(parse_error(R"([{"op":"crease","edges":"sharp","angle":200,"sharpness":3}])"),
            "o: ops[0] (crease): \"angle\" must be from 0 to less than 180 degrees");
  EXPECT_EQ(parse_error(R"([{"op":"crease","edges":"sharp","sharpness":3}])"),
            "o: ops[0] (crease): \"angle\" is missing");
  EXPECT_EQ(parse_error(R"([{"op":"crease","edges":[[0,1]],"angle":30,"sharpness":3}])"),
            "o: ops[0] (crease): unknown key 'angle'");
}

}  // namespace
}  // namespace gps
