// A bevel at the largest width and on triangles (core/modelling/bevel.h): the new vertices that meet
// are merged, a width that moves them by nothing is refused, and no face is left without area.
#include <gtest/gtest.h>

#include <numeric>

#include "core/modelling/bevel.h"
#include "core/modelling/extrude.h"
#include "core/modelling/samples.h"
#include "tests/support/bevel_width.h"
#include "tests/support/error_of.h"
#include "tests/support/mesh_checks.h"

namespace gps {
namespace {

using test::error_of;
using test::width;

// At the clamped width the vertices that meet are merged, and the faces left without area removed:
// a cube bevelled on every edge becomes the octahedron of its faces' centres, on every vertex the
// cuboctahedron of its edges' midpoints, with no two vertices at one point.
TEST(BevelEdges, AClampedWidthLeavesNoCoincidentVerticesNorFacesWithoutArea) {
  const CovarianceMesh cube = make_sample("cube");
  std::vector<std::array<int, 2>> every_edge;
  for (size_t e = 0; e < cube.n_edges(); ++e) every_edge.push_back({cube.edge(e)[0], cube.edge(e)[1]});
  std::vector<int> every_vertex(8);
  std::iota(every_vertex.begin(), every_vertex.end(), 0);
  struct Case {
    Modelled result;
    size_t vertices, faces;
  };
  BevelOptions two = width(1.5, 2);
  const Case cases[] = {{bevel_edges(cube, every_edge, width(1.5)), 6, 8},
                        {bevel_edges(cube, every_edge, two), 18, 8},
                        {bevel_vertices(cube, every_vertex, width(1.5)), 12, 14},
                        {bevel_vertices(cube, every_vertex, two), 36, 14},
                        {bevel_edges(cube, {{4, 5}}, width(5)), 6, 5},
                        {bevel_edges(cube, {{4, 5}}, width(2)), 6, 5},           // at the limit, not clamped
                        {bevel_edges(cube, every_edge, width(1 - 1e-7)), 6, 8},  // within the weld tolerance
                        {bevel_vertices(cube, {0}, width(2)), 7, 7}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.result.summary);
    const CovarianceMesh& m = c.result.mesh;
    EXPECT_EQ(m.n_vertices(), c.vertices);
    EXPECT_EQ(m.n_faces(), c.faces);
    const test::Shape shape = test::shape_of(m);
    EXPECT_EQ(shape.boundary_edges, 0);
    EXPECT_TRUE(shape.oriented);
    for (size_t v = 0; v < m.n_vertices(); ++v)
      for (size_t w = v + 1; w < m.n_vertices(); ++w) EXPECT_GT((m.mean(v) - m.mean(w)).norm(), 1e-6) << v << " " << w;
    const MeshArrays a = arrays_of(m);
    for (int f = 0; f < a.n_faces(); ++f) EXPECT_GT(newell_normal(a, f).norm(), 1e-6) << "face " << f;
    for (const int v : c.result.selection) EXPECT_LT(size_t(v), m.n_vertices());
  }
  // A width at its limit but for rounding is not reported as clamped (50 % of a cylinder's edges at
  // every vertex of a ring said "width clamped to 50").
  BevelOptions half = width(50);
  half.width_type = BevelWidth::percent;
  const Modelled ring = bevel_vertices(make_sample("cylinder"), {0, 1, 2, 3, 4, 5, 6, 7}, half);
  EXPECT_EQ(ring.summary.find("clamped"), std::string::npos) << ring.summary;
  // A width that leaves new vertices within a millionth of the mesh's size of where they start is refused.
  EXPECT_EQ(error_of([&] {
              bevel_edges(cube, {{4, 5}}, width(1e-12));
            }).find("a width of 1e-12 would leave new vertices at vertex "),
            0u);
  // The octahedron's vertices are the centres of the cube's faces.
  for (size_t v = 0; v < 6; ++v) EXPECT_NEAR(cases[0].result.mesh.mean(v).cwiseAbs().sum(), 1.0, 1e-12);
}

// On a mesh of triangles the faces a bevel widens are split into triangles none of which is flat (a
// corner on the line of its neighbours is joined across, not left as the tip of a sliver).
TEST(BevelEdges, TheTrianglesOfAWidenedFaceAllHaveArea) {
  const CovarianceMesh ico = make_sample("icosphere", 80);
  for (const int segments : {1, 2, 3}) {
    const Modelled r = bevel_edges(ico, {{12, 13}}, width(0.05, segments));
    const MeshArrays a = arrays_of(r.mesh);
    for (int f = 0; f < a.n_faces(); ++f) {
      ASSERT_EQ(a.faces[size_t(f)].size(), 3u);
      EXPECT_GT(newell_normal(a, f).norm(), 1e-6) << "face " << f << " of " << segments << " segments";
    }
  }
}

}  // namespace
}  // namespace gps
