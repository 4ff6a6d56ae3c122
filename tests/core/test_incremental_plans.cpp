// Plans kept through modelling operations (core/plans/surface_replanner.h, set_topology): after random
// sequences of every kind of operation and sharpness change on quad, triangle, mixed, open and creased
// meshes, the incrementally kept tables equal a full re-plan's bit for bit, also when undone and redone
// (the way back given by the inverse origins), whatever origin is given; and a small operation builds
// only a few ranges again.
#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "core/modelling/bevel.h"
#include "core/modelling/crease_edges.h"
#include "core/modelling/delete_elements.h"
#include "core/modelling/edge_operations.h"
#include "core/modelling/extrude.h"
#include "core/modelling/inset.h"
#include "core/modelling/loop_cut.h"
#include "core/modelling/merge_vertices.h"
#include "core/modelling/primitives.h"
#include "core/modelling/samples.h"
#include "core/modelling/subdivide_mesh.h"
#include "core/plans/surface_replanner.h"
#include "core/support/error.h"
#include "tests/support/plan_tables.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

struct Case {
  std::string name;
  CovarianceMesh mesh;
  Scheme scheme;
  int operations = 14;  // fewer for Loop, whose full re-plans build their exact tables afresh
};

CovarianceMesh creased(CovarianceMesh m, double sharpness) {
  const MeshConnectivity c = connectivity_of(topology_of(m.mesh));
  for (int e = 0; e < c.n_edges(); e += 7)
    m.sharpness.set_crease(c.edge_verts[2 * size_t(e)], c.edge_verts[2 * size_t(e) + 1], sharpness);
  return m;
}

std::vector<Case> cases() {
  return {{"sphere (closed quads)", make_sample("sphere", 400), Scheme::catmull_clark},
          {"grid (open quads, creased)", creased(test::grid_mesh(8, 6), 2.0), Scheme::catmull_clark},
          {"cylinder (quads and octagons)", make_sample("cylinder"), Scheme::catmull_clark},
          {"cube (creased infinitely)", creased(test::cube_mesh(), kInfiniteSharpness), Scheme::catmull_clark},
          {"icosphere (triangles, creased)", creased(make_sample("icosphere", 300), 1.5), Scheme::loop, 8},
          {"triangle grid (open triangles, creased)", creased(test::triangle_grid_mesh(5, 4), kInfiniteSharpness),
           Scheme::loop, 8},
          {"icosphere (smooth triangles)", make_sample("icosphere", 80), Scheme::loop, 8}};
}

// One random operation on `m`; throws gps::Error where the operation refuses.
Modelled random_operation(const CovarianceMesh& m, std::mt19937& random) {
  const PolygonTopology t = topology_of(m.mesh);
  const MeshConnectivity c = connectivity_of(t);
  const auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(random); };
  const int f = pick(t.n_faces()), e = pick(c.n_edges()), v = pick(t.n_vertices);
  const int a = c.edge_verts[2 * size_t(e)], b = c.edge_verts[2 * size_t(e) + 1];
  const double sharpness[] = {0.0, 1.0, 2.5, kInfiniteSharpness};
  BevelOptions bevel;
  bevel.width = 0.02;
  bevel.segments = 1 + pick(2);
  switch (pick(14)) {
    case 0:
      return extrude_faces(m, {f}, 0.05);
    case 1:
      return inset_faces(m, {f}, 0.01);
    case 2:
      return loop_cut(m, a, b, 1 + pick(2));
    case 3:
      return subdivide_faces(m, {f});
    case 4:
      return delete_faces(m, {f});
    case 5:
      return merge_vertices(m, {a, b}, MergePoint::center);
    case 6:
      return split_edge(m, a, b);
    case 7:
      return bevel_edges(m, {{a, b}}, bevel);
    case 8:
      return dissolve_edges(m, {{a, b}});
    case 9:
      return set_crease(m, {{a, b}}, sharpness[pick(4)]);
    case 10:
      return set_corner(m, {v}, sharpness[pick(4)]);
    case 11:
      return delete_vertices(m, {v});
    case 12:
      return add_primitive(m, Primitive::cube, Vec3(3, 0, 0), 0.5);
    default:
      return extrude_faces(m, {f, (f + 1) % t.n_faces()}, -0.02);
  }
}

// Random operations, each followed by the replanner: equal to a full re-plan after the operation, after
// its undo and after its redo.
TEST(IncrementalPlans, RandomOperationsMatchAFullReplan) {
  for (const Case& c : cases()) {
    PlanOptions options;
    options.scheme = c.scheme;
    CovarianceMesh mesh = c.mesh;
    SurfaceReplanner replanner(topology_of(mesh.mesh), options, mesh.sharpness, test::kSmallRanges);
    std::mt19937 random(11);
    int applied = 0, planned = 0, faces = 0;
    for (int step = 0; step < 40 && applied < c.operations; ++step) {
      Modelled result;
      try {
        result = random_operation(mesh, random);
      } catch (const Error&) {
        continue;  // a refusal: nothing to re-plan
      }
      const std::string where = c.name + ", step " + std::to_string(step) + " (" + result.summary + ")";
      const PolygonTopology after = topology_of(result.mesh.mesh);
      SurfaceTables full;
      try {
        full = build_surface_plans(after, options, result.mesh.sharpness);
      } catch (const Error&) {  // quads in a mesh planned by Loop: refused alike, and nothing changes
        const SurfaceTables before = replanner.tables();
        EXPECT_THROW(replanner.set_topology(after, result.mesh.sharpness, result.vertex_origin), Error) << where;
        test::expect_same_tables(replanner.tables(), before, where + ", refused");
        continue;
      }
      ++applied;
      planned += replanner.set_topology(after, result.mesh.sharpness, result.vertex_origin);
      faces += after.n_faces();
      test::expect_same_tables(replanner.tables(), full, where);
      const PolygonTopology before = topology_of(mesh.mesh);
      const std::vector<int> back = inverse_origin(result.vertex_origin, mesh.n_vertices());
      replanner.set_topology(before, mesh.sharpness, back);
      test::expect_same_tables(replanner.tables(), build_surface_plans(before, options, mesh.sharpness),
                               where + ", undone");
      replanner.set_topology(after, result.mesh.sharpness, result.vertex_origin);
      test::expect_same_tables(replanner.tables(), build_surface_plans(after, options, result.mesh.sharpness),
                               where + ", redone");
      mesh = std::move(result.mesh);
    }
    EXPECT_GE(applied, c.operations - 4) << c.name;
    // Loop's smooth builder plans the whole mesh; on a mesh of a few dozen faces every piece is most of it.
    if (c.name != "icosphere (smooth triangles)" && c.mesh.n_faces() > 200)
      EXPECT_LT(planned, faces / 2) << c.name << ": most faces kept their plans";
  }
}

// The origin only says where to look: origins that do not fit the operation (every vertex said to be
// new, or kept where the operation renumbered them) still give a full re-plan's tables.
TEST(IncrementalPlans, AnyOriginGivesTheTablesOfAFullReplan) {
  const CovarianceMesh sphere = make_sample("sphere", 300);
  PlanOptions options;
  const Modelled removed = delete_faces(sphere, {5, 40});
  const PolygonTopology after = topology_of(removed.mesh.mesh);
  const std::vector<std::vector<int>> origins = {
      {}, std::vector<int>(removed.mesh.n_vertices(), -1), removed.vertex_origin, {0, 2, 1}};
  for (size_t i = 0; i < origins.size(); ++i) {
    SurfaceReplanner replanner(topology_of(sphere.mesh), options, {}, test::kSmallRanges);
    replanner.set_topology(after, {}, origins[i]);
    test::expect_same_tables(replanner.tables(), build_surface_plans(after, options, {}),
                             "origin " + std::to_string(i));
  }
}

// One extruded face of a 6,144-face sphere builds again the ranges around it and its new faces, not the mesh.
TEST(IncrementalPlans, AnExtrudeBuildsAFewRangesAgain) {
  const CovarianceMesh sphere = make_sample("sphere", 6000);
  PlanOptions options;
  SurfaceReplanner replanner(topology_of(sphere.mesh), options, {});
  const Modelled extruded = extrude_faces(sphere, {int(sphere.n_faces() / 2)}, 0.01);
  const PolygonTopology after = topology_of(extruded.mesh.mesh);
  const int planned = replanner.set_topology(after, {}, extruded.vertex_origin);
  EXPECT_LE(planned, 4 * SurfaceReplanner::kFacesPerRange);
  EXPECT_GT(planned, 0);
  test::expect_same_tables(replanner.tables(), build_surface_plans(after, options, {}), "extruded");
}

// A topology the plans refuse (a crease between unjoined vertices) leaves the tables as they were.
TEST(IncrementalPlans, ARefusedTopologyChangesNothing) {
  const CovarianceMesh grid = test::grid_mesh(3, 3);
  SurfaceReplanner replanner(topology_of(grid.mesh), {}, {});
  const SurfaceTables before = replanner.tables();
  Sharpness bad;
  bad.set_crease(0, 15, 2.0);
  EXPECT_THROW(replanner.set_topology(topology_of(grid.mesh), bad), Error);
  test::expect_same_tables(replanner.tables(), before, "after the refusal");
  const Modelled extruded = extrude_faces(grid, {4}, 0.1);
  replanner.set_topology(topology_of(extruded.mesh.mesh), {}, extruded.vertex_origin);
  test::expect_same_tables(replanner.tables(), build_surface_plans(topology_of(extruded.mesh.mesh), {}, {}),
                           "after the refusal, an extrude");
}

}  // namespace
}  // namespace gps
