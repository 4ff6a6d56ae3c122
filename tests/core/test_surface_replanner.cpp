// A sharpness change re-planned incrementally (core/plans/surface_replanner.h) gives the tables of a
// full re-plan bit for bit: random edges and corners of creased Catmull-Clark and Loop meshes, open and
// closed, set semi-sharp, infinitely sharp and back to 0; and only the faces whose pieces hold a change
// are built again.
#include <gtest/gtest.h>

#include <array>
#include <random>

#include "core/support/error.h"
#include "core/modelling/samples.h"
#include "core/plans/planned_surface.h"
#include "core/plans/surface_replanner.h"
#include "tests/support/plan_tables.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

struct Case {
  std::string name;
  CovarianceMesh mesh;
  Scheme scheme;
  int depth = kExactPlanDepth;
  bool exact = true;
  PlanOptions options() const {
    PlanOptions o;
    o.scheme = scheme;
    o.depth = depth;
    o.exact = exact;
    return o;
  }
};

std::vector<Case> cases() {
  return {{"grid (open quads)", test::grid_mesh(9, 7), Scheme::catmull_clark},
          {"sphere (closed quads, valence 3)", make_sample("sphere", 600), Scheme::catmull_clark},
          {"cylinder (octagons split)", make_sample("cylinder"), Scheme::catmull_clark},
          {"icosphere (closed triangles)", make_sample("icosphere", 500), Scheme::loop},
          {"triangle grid (open triangles)", test::triangle_grid_mesh(8, 7), Scheme::loop},
          {"open cylinder (open quads)", test::open_cylinder_mesh(), Scheme::catmull_clark},
          {"sphere, exact nodes at depth 0", make_sample("sphere", 200), Scheme::catmull_clark, 0},
          {"torus, Bezier plans", make_sample("torus"), Scheme::catmull_clark, 3, false}};
}

// Random edges and corners set to a random sharpness among semi-sharp, infinite and 0, keeping a few
// creases throughout so that the changes stay incremental; each step against a full re-plan.
TEST(SurfaceReplanner, RandomChangesMatchAFullReplan) {
  const double values[] = {0.0, 0.0, 0.5, 1.0, 1.7, 2.5, 4.0, kInfiniteSharpness, 12.0};
  for (const Case& c : cases()) {
    const PolygonTopology& topology = c.mesh.topology();
    std::vector<std::pair<int, int>> ends;
    for (size_t e = 0; e < c.mesh.n_edges(); ++e) ends.emplace_back(c.mesh.edge(e)[0], c.mesh.edge(e)[1]);
    const int n_vertices = int(c.mesh.n_vertices());
    std::mt19937 random(7);
    const auto any_edge = [&] { return ends[std::uniform_int_distribution<size_t>(0, ends.size() - 1)(random)]; };
    const auto any_value = [&] { return values[std::uniform_int_distribution<int>(0, 8)(random)]; };
    Sharpness sharpness;
    for (int i = 0; i < 3; ++i) {  // kept through the steps (never 0)
      const auto [a, b] = ends[size_t(i) * ends.size() / 3];
      sharpness.set_crease(a, b, i == 0 ? 2.0 : kInfiniteSharpness);
    }
    const PlanOptions options = c.options();
    SurfaceReplanner replanner(topology, options, sharpness, test::kSmallRanges);
    test::expect_same_tables(replanner.tables(), build_surface_plans(topology, options, sharpness),
                             c.name + ", first plan");
    int partial = 0;
    for (int step = 0; step < 12; ++step) {
      const int changes = std::uniform_int_distribution<int>(1, 3)(random);
      for (int k = 0; k < changes; ++k) {
        if (std::uniform_int_distribution<int>(0, 3)(random) == 0) {
          sharpness.set_corner(std::uniform_int_distribution<int>(0, n_vertices - 1)(random), any_value(), n_vertices);
        } else {
          auto [a, b] = any_edge();
          if (sharpness.crease(a, b) > 0.0 && std::uniform_int_distribution<int>(0, 1)(random) == 0)
            sharpness.set_crease(a, b, 0.0);  // a crease back to 0
          else
            sharpness.set_crease(a, b, any_value());
        }
      }
      for (int i = 0; i < 3; ++i) {
        const auto [a, b] = ends[size_t(i) * ends.size() / 3];
        if (sharpness.crease(a, b) == 0.0) sharpness.set_crease(a, b, 3.0);
      }
      const std::vector<int> faces = replanner.set_sharpness(sharpness);
      partial += faces.size() < size_t(topology.n_faces()) ? 1 : 0;
      test::expect_same_tables(replanner.tables(), build_surface_plans(topology, options, sharpness),
                               c.name + ", step " + std::to_string(step));
    }
    EXPECT_GT(partial, 6) << c.name << ": most steps re-plan only some faces";
  }
}

// A long session of crease edits, each at another edge, cuts range after range: the pieces are joined
// again, so the ranges stay as few as the faces need (any two neighbours hold half a range's faces) and
// the tables stay those of a full re-plan. Edits all over the mesh, and edits that sweep along it, which
// join a range the last merge kept in place to one built now.
TEST(SurfaceReplanner, CreaseEditsEverywhereLeaveAsFewRangesAsTheFacesNeed) {
  const CovarianceMesh mesh = make_sample("sphere", 3000);
  const PolygonTopology& topology = mesh.topology();
  const int faces_per_range = 128, n_faces = topology.n_faces();
  const int filled = (n_faces + faces_per_range - 1) / faces_per_range;
  // Per session: the stride from edge to edge, the steps, and every how many steps the tables are checked.
  for (const auto [stride, steps, checked] : {std::array<int, 3>{7919, 80, 20}, std::array<int, 3>{57, 24, 1}}) {
    Sharpness sharpness;
    sharpness.set_crease(mesh.edge(0)[0], mesh.edge(0)[1], 2.0);  // kept throughout
    SurfaceReplanner replanner(topology, {}, sharpness, faces_per_range);
    ASSERT_EQ(replanner.n_ranges(), filled);
    for (int step = 1; step <= steps; ++step) {
      const std::string where = "stride " + std::to_string(stride) + ", step " + std::to_string(step);
      const auto e = mesh.edge(size_t(step) * size_t(stride) % (mesh.n_edges() - 1) + 1);  // never edge 0
      sharpness.set_crease(e[0], e[1], sharpness.crease(e[0], e[1]) > 0.0 ? 0.0 : 2.5);
      ASSERT_LT(replanner.set_sharpness(sharpness).size(), size_t(n_faces)) << where;
      ASSERT_LE(replanner.n_ranges(), 4 * filled + 1) << where;
      if (step % checked == 0)
        test::expect_same_tables(replanner.tables(), build_surface_plans(topology, {}, sharpness), where);
    }
  }
}

// The first crease of a smooth mesh and the removal of the last one re-plan everything (the plans'
// depth bound, and Loop's smooth builder), and still match.
TEST(SurfaceReplanner, FirstAndLastCrease) {
  for (const Case& c : cases()) {
    const PolygonTopology& topology = c.mesh.topology();
    const PlanOptions options = c.options();
    SurfaceReplanner replanner(topology, options, {}, test::kSmallRanges);
    const auto [a, b] = c.mesh.edge(0);
    Sharpness one;
    one.set_crease(a, b, 1.5);
    EXPECT_EQ(replanner.set_sharpness(one).size(), size_t(topology.n_faces())) << c.name;
    test::expect_same_tables(replanner.tables(), build_surface_plans(topology, options, one),
                             c.name + ", first crease");
    one.set_crease(a, b, 0.0);
    EXPECT_EQ(replanner.set_sharpness(one).size(), size_t(topology.n_faces())) << c.name;
    test::expect_same_tables(replanner.tables(), build_surface_plans(topology, options, {}),
                             c.name + ", last crease gone");
    EXPECT_TRUE(replanner.set_sharpness(one).empty()) << c.name << ": nothing changed";
  }
}

// The faces that read an edge: those sharing a vertex with a face that holds it (the grid's interior
// edge between faces 0 and 1 of a 4 × 1 strip reaches faces 0..2, not 3).
TEST(SurfaceReplanner, FacesReadingAnEdge) {
  const CovarianceMesh strip = test::grid_mesh(4, 1);
  const PolygonTopology& t = strip.topology();
  const MeshConnectivity& c = strip.connectivity();
  int shared = -1;
  for (int e = 0; e < c.n_edges(); ++e)
    if (!c.is_boundary_edge(e) && std::min(c.edge_faces[2 * size_t(e)], c.edge_faces[2 * size_t(e) + 1]) == 0)
      shared = e;
  ASSERT_GE(shared, 0);
  EXPECT_EQ(faces_reading(t, c, {shared}, {}), (std::vector<int>{0, 1, 2}));
}

// A mesh with an unjoined crease is refused with the tables as they were.
TEST(SurfaceReplanner, UnjoinedCreaseIsRefused) {
  const CovarianceMesh grid = test::grid_mesh(3, 3);
  const PolygonTopology& topology = grid.topology();
  SurfaceReplanner replanner(topology, {}, {});
  const SurfaceTables before = replanner.tables();
  Sharpness bad;
  bad.set_crease(0, 15, 2.0);
  EXPECT_THROW(replanner.set_sharpness(bad), Error);
  test::expect_same_tables(replanner.tables(), before, "after the refusal");
}

}  // namespace
}  // namespace gps
