// Plans kept through modelling operations (core/plans/surface_replanner.h, set_topology): after random
// sequences of every kind of operation and sharpness change on quad, triangle, mixed, open and creased
// meshes, the incrementally kept tables equal a full re-plan's bit for bit, also when undone and redone
// (the way back given by the inverse origins), whatever origin is given; a change names the kept
// patches whose adjacency records it changed; and a small operation builds only a few ranges again.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>

#include "core/mesh/mesh_delta.h"
#include "core/modelling/crease_edges.h"
#include "core/modelling/delete_elements.h"
#include "core/modelling/extrude.h"
#include "core/modelling/fill.h"
#include "core/modelling/loop_cut.h"
#include "core/modelling/mesh_arrays.h"
#include "core/modelling/merge_vertices.h"
#include "core/modelling/subdivide_mesh.h"
#include "core/modelling/samples.h"
#include "core/plans/kept_patch_records.h"
#include "core/plans/surface_replanner.h"
#include "core/support/error.h"
#include "tests/support/plan_tables.h"
#include "tests/support/random_operations.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

// The replanner's last change names, among its relinked patches, every kept patch whose adjacency
// records are not those it had in `before` (renumbered); returns whether it named its relinked patches.
bool expect_relinked_named(const SurfaceTables& before, const SurfaceReplanner& replanner, const std::string& where) {
  const PlanChange& change = replanner.last_change();
  if (!change.relinked) return false;
  const PatchPlans& after = replanner.tables().plans;
  EXPECT_TRUE(kept_runs_fit(change.kept, before.plans.n_patches(), after.n_patches())) << where;
  EXPECT_TRUE(std::is_sorted(change.relinked->begin(), change.relinked->end())) << where;
  EXPECT_EQ(patches_not_kept_alike(before.plans, after, change.kept, &*change.relinked),
            patches_not_kept_alike(before.plans, after, change.kept))
      << where << ": a kept patch relinked but not named";
  return true;
}

// The replanner's last change keeps stencil rows only where they have the terms of the rows named in
// `before`, their vertices renumbered as `origin` says (per new vertex its old index), in runs that
// increase in both; returns how many rows it kept.
int expect_kept_rows_alike(const SurfaceTables& before, const SurfaceReplanner& replanner,
                           const std::vector<int>& origin, const std::string& where) {
  const StencilTable &then = before.stencils, &now = replanner.tables().stencils;
  std::vector<int> new_index(size_t(then.n_base), -1);
  for (int v = 0; v < now.n_base; ++v)
    if (const int o = origin.empty() ? v : origin[size_t(v)]; o >= 0 && o < then.n_base) new_index[size_t(o)] = v;
  int kept = 0, last = -1, last_old = -1;
  for (const KeptStencilRows& run : replanner.last_change().kept_rows) {
    EXPECT_TRUE(run.first > last && run.old_first > last_old && run.count > 0) << where;
    EXPECT_LE(run.first + run.count, now.n_rows()) << where;
    EXPECT_LE(run.old_first + run.count, then.n_rows()) << where;
    if (run.first + run.count > now.n_rows() || run.old_first + run.count > then.n_rows()) return kept;
    for (int i = 0; i < run.count; ++i) {
      const int r = run.first + i, o = run.old_first + i;
      const auto terms = [](const StencilTable& t, int row) {
        const auto b = size_t(t.offsets[size_t(row)]), e = size_t(t.offsets[size_t(row) + 1]);
        return std::pair{std::vector<int>(t.indices.begin() + long(b), t.indices.begin() + long(e)),
                         std::vector<double>(t.weights.begin() + long(b), t.weights.begin() + long(e))};
      };
      auto old_terms = terms(then, o);
      for (int& index : old_terms.first) index = new_index[size_t(index)];
      EXPECT_EQ(terms(now, r), old_terms) << where << ": row " << r << " kept from row " << o;
    }
    kept += run.count;
    last = run.first + run.count - 1;
    last_old = run.old_first + run.count - 1;
  }
  return kept;
}

// Random operations, each followed by the replanner: equal to a full re-plan after the operation, after
// its undo and after its redo; the kept patches whose records changed named, the kept rows alike.
TEST(IncrementalPlans, RandomOperationsMatchAFullReplan) {
  int named = 0, kept_rows = 0;
  for (const test::RandomOperationCase& c : test::random_operation_cases()) {
    PlanOptions options;
    options.scheme = c.scheme;
    CovarianceMesh mesh = c.mesh;
    SurfaceReplanner replanner(mesh.topology(), options, mesh.sharpness, test::kSmallRanges);
    std::mt19937 random(11);
    // A full re-plan of `mesh`, the tables its undo is held to (the last step's `full`).
    SurfaceTables mesh_full = build_surface_plans(mesh.topology(), options, mesh.sharpness);
    int applied = 0, planned = 0, faces = 0;
    for (int step = 0; step < 40 && applied < c.operations; ++step) {
      Modelled result;
      try {
        result = test::random_operation(mesh, random);
      } catch (const Error&) {
        continue;  // a refusal: nothing to re-plan
      }
      const std::string where = c.name + ", step " + std::to_string(step) + " (" + result.summary + ")";
      const PolygonTopology& after = result.mesh.topology();
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
      named += expect_relinked_named(mesh_full, replanner, where);
      kept_rows += expect_kept_rows_alike(mesh_full, replanner, result.vertex_origin, where);
      const PolygonTopology& before = mesh.topology();
      const std::vector<int> back = inverse_origin(result.vertex_origin, mesh.n_vertices());
      replanner.set_topology(before, mesh.sharpness, back);
      test::expect_same_tables(replanner.tables(), mesh_full, where + ", undone");
      named += expect_relinked_named(full, replanner, where + ", undone");
      kept_rows += expect_kept_rows_alike(full, replanner, back, where + ", undone");
      replanner.set_topology(after, result.mesh.sharpness, result.vertex_origin);
      test::expect_same_tables(replanner.tables(), full, where + ", redone");
      mesh = std::move(result.mesh);
      mesh_full = std::move(full);
    }
    EXPECT_GE(applied, c.operations - 4) << c.name;
    // On a mesh of a few dozen faces every piece is most of it.
    if (c.mesh.n_faces() > 200) {
      EXPECT_LT(planned, faces / 2) << c.name << ": most faces kept their plans";
    }
  }
  EXPECT_GT(named, 50) << "changes that named their relinked patches";
  EXPECT_GT(kept_rows, 1000) << "stencil rows kept";
}

// Each kind of operation, on each mesh it applies to (up to a few tries at random elements), re-planned
// from the mesh before it and back: a full re-plan's tables both ways. Every kind applies somewhere.
TEST(IncrementalPlans, EveryKindOfOperationMatchesAFullReplan) {
  std::vector<int> applied(size_t(test::kOperationKinds), 0);
  std::mt19937 random(7);
  for (const test::RandomOperationCase& c : test::random_operation_cases()) {
    PlanOptions options;
    options.scheme = c.scheme;
    const SurfaceTables mesh_full = build_surface_plans(c.mesh.topology(), options, c.mesh.sharpness);
    for (int kind = 0; kind < test::kOperationKinds; ++kind) {
      for (int attempt = 0; attempt < 6; ++attempt) {
        Modelled result;
        SurfaceTables full;
        try {
          result = test::operation_of_kind(c.mesh, kind, random);
          full = build_surface_plans(result.mesh.topology(), options, result.mesh.sharpness);
        } catch (const Error&) {
          continue;  // refused by the operation, or quads in a mesh planned by Loop
        }
        const std::string where = c.name + ", kind " + std::to_string(kind) + " (" + result.summary + ")";
        SurfaceReplanner replanner(c.mesh.topology(), options, c.mesh.sharpness, test::kSmallRanges);
        replanner.set_topology(result.mesh.topology(), result.mesh.sharpness, result.vertex_origin);
        test::expect_same_tables(replanner.tables(), full, where);
        replanner.set_topology(c.mesh.topology(), c.mesh.sharpness,
                               inverse_origin(result.vertex_origin, c.mesh.n_vertices()));
        test::expect_same_tables(replanner.tables(), mesh_full, where + ", undone");
        ++applied[size_t(kind)];
        break;
      }
    }
  }
  for (int kind = 0; kind < test::kOperationKinds; ++kind)
    EXPECT_GT(applied[size_t(kind)], 0) << "operation kind " << kind << " applied to none of the meshes";
}

// On a mesh past kParallelFaces faces the replanner matches faces and follows the patch adjacency on
// all cores: random operations, each undone, still give a full re-plan's tables.
TEST(IncrementalPlans, RandomOperationsOnALargeMeshMatchAFullReplan) {
  CovarianceMesh mesh = make_sample("sphere", 6000);
  ASSERT_GE(mesh.n_faces(), size_t(kParallelFaces));
  const PlanOptions options;
  SurfaceReplanner replanner(mesh, options);
  SurfaceTables mesh_full = build_surface_plans(mesh.topology(), options, mesh.sharpness);
  std::mt19937 random(46);
  int applied = 0;
  for (int step = 0; step < 30 && applied < 6; ++step) {
    Modelled result;
    try {
      result = test::random_operation(mesh, random);
    } catch (const Error&) {
      continue;
    }
    const std::string where = "step " + std::to_string(step) + " (" + result.summary + ")";
    ++applied;
    SurfaceTables full = build_surface_plans(result.mesh.topology(), options, result.mesh.sharpness);
    replanner.set_topology(result.mesh, result.vertex_origin);
    test::expect_same_tables(replanner.tables(), full, where);
    EXPECT_TRUE(expect_relinked_named(mesh_full, replanner, where));
    expect_kept_rows_alike(mesh_full, replanner, result.vertex_origin, where);
    replanner.set_topology(mesh, inverse_origin(result.vertex_origin, mesh.n_vertices()));
    test::expect_same_tables(replanner.tables(), mesh_full, where + ", undone");
    EXPECT_TRUE(expect_relinked_named(full, replanner, where + ", undone"));
    replanner.set_topology(result.mesh, result.vertex_origin);
    mesh = std::move(result.mesh);
    mesh_full = std::move(full);
  }
  EXPECT_EQ(applied, 6);
}

// The origin only says where to look: origins that do not fit the operation (every vertex said to be
// new, or kept where the operation renumbered them) still give a full re-plan's tables.
TEST(IncrementalPlans, AnyOriginGivesTheTablesOfAFullReplan) {
  const CovarianceMesh sphere = make_sample("sphere", 300);
  PlanOptions options;
  const Modelled removed = delete_faces(sphere, {5, 40});
  const PolygonTopology& after = removed.mesh.topology();
  const std::vector<std::vector<int>> origins = {
      {}, std::vector<int>(removed.mesh.n_vertices(), -1), removed.vertex_origin, {0, 2, 1}};
  for (size_t i = 0; i < origins.size(); ++i) {
    SurfaceReplanner replanner(sphere.topology(), options, {}, test::kSmallRanges);
    replanner.set_topology(after, {}, origins[i]);
    test::expect_same_tables(replanner.tables(), build_surface_plans(after, options, {}),
                             "origin " + std::to_string(i));
  }
}

// One extruded face of a 6,144-face sphere builds again the ranges around it and its new faces, not the mesh.
TEST(IncrementalPlans, AnExtrudeBuildsAFewRangesAgain) {
  const CovarianceMesh sphere = make_sample("sphere", 6000);
  PlanOptions options;
  SurfaceReplanner replanner(sphere.topology(), options, {});
  const Modelled extruded = extrude_faces(sphere, {int(sphere.n_faces() / 2)}, 0.01);
  const PolygonTopology& after = extruded.mesh.topology();
  const int planned = replanner.set_topology(after, {}, extruded.vertex_origin);
  EXPECT_LE(planned, SurfaceReplanner::kFacesPerRange / 2);  // the faces around it, not their ranges
  EXPECT_GT(planned, 0);
  test::expect_same_tables(replanner.tables(), build_surface_plans(after, options, {}), "extruded");
}

// The replanner, which has planned `before`, given a change's result and then `before` again (its
// undo): each time the faces around the change are planned again, not their ranges, and the tables
// are a full plan's.
void expect_planned_where_it_reaches(SurfaceReplanner& replanner, const Modelled& changed, const CovarianceMesh& before,
                                     const PlanOptions& options, const std::string& where) {
  const int planned = replanner.set_topology(changed.mesh, changed.vertex_origin);
  EXPECT_GT(planned, 0) << where;
  EXPECT_LE(planned, SurfaceReplanner::kFacesPerRange / 2) << where;
  test::expect_same_tables(replanner.tables(), build_surface_plans(changed.mesh, options), where);
  EXPECT_LE(replanner.set_topology(before, {}), SurfaceReplanner::kFacesPerRange / 2) << where << ", undone";
  test::expect_same_tables(replanner.tables(), build_surface_plans(before, options), where + ", undone");
}

// The first crease or corner of a Catmull-Clark mesh is planned as any later one: the faces around it
// again, not the whole mesh (one builder plans creased and smooth quads alike); and back to smooth.
TEST(IncrementalPlans, AFirstCreaseOrCornerOfAQuadMeshBuildsTheFacesAroundIt) {
  const CovarianceMesh sphere = make_sample("sphere", 6000);
  const PlanOptions options;
  SurfaceReplanner replanner(sphere, options);
  const std::array<int, 2> edge = sphere.edge(sphere.n_faces());
  for (const double sharpness : {2.0, kInfiniteSharpness}) {
    for (const bool corner : {false, true}) {
      const Modelled sharp =
          corner ? set_corner(sphere, {edge[0]}, sharpness) : set_crease(sphere, {{edge[0], edge[1]}}, sharpness);
      expect_planned_where_it_reaches(replanner, sharp, sphere, options, sharp.summary);
    }
  }
}

// A crease or corner changed on a mesh with sharpness already, and its undo, share the planned mesh's
// faces (CovarianceMesh::shape): re-planned where the change reaches, as set_sharpness does, bit for
// bit, on quads and on triangles.
TEST(IncrementalPlans, ASharpnessChangeOnTheSameFacesIsPlannedWhereItReaches) {
  const PlanOptions options;
  for (const char* name : {"sphere", "icosphere"}) {
    CovarianceMesh mesh = make_sample(name, 6000);
    const std::array<int, 2> first = mesh.edge(7), second = mesh.edge(mesh.n_edges() / 2);
    mesh.sharpness.set_crease(first[0], first[1], 2.0);
    SurfaceReplanner replanner(mesh, options);
    for (const bool corner : {false, true}) {
      const Modelled sharp = corner ? set_corner(mesh, {second[0]}, 3.0) : set_crease(mesh, {second}, 3.0);
      ASSERT_EQ(sharp.mesh.shape(), mesh.shape()) << sharp.summary;
      expect_planned_where_it_reaches(replanner, sharp, mesh, options, std::string(name) + ": " + sharp.summary);
    }
  }
}

// A mesh made by an operation, or restored by its undo, carries the faces its update found continued:
// the replanner takes them from it instead of matching the faces again, and keeps what matching keeps,
// bit for bit.
TEST(IncrementalPlans, TheFacesAnOperationContinuedAreTakenAsMatchingFindsThem) {
  const CovarianceMesh sphere = make_sample("sphere", 6000);
  const int f = int(sphere.n_faces() / 2);
  const std::span<const int> corners = sphere.face(size_t(f));
  const std::vector<std::pair<const char*, Modelled>> operations = {
      {"extrude", extrude_faces(sphere, {f}, 0.01)},
      {"loop cut", loop_cut(sphere, corners[0], corners[1], 1)},
      {"delete", delete_faces(sphere, {f})},
      {"subdivide", subdivide_faces(sphere, {f})},
      {"merge", merge_vertices(sphere, {corners[0], corners[1]}, MergePoint::center)}};
  for (const auto& [name, operation] : operations) {
    SCOPED_TRACE(name);
    const std::vector<int> back = inverse_origin(operation.vertex_origin, sphere.n_vertices());
    const CovarianceMesh restored = apply_delta(operation.mesh, mesh_delta(operation.mesh, sphere, back));
    for (const auto& [from, to, origin] : {std::tuple{&sphere, &operation.mesh, &operation.vertex_origin},
                                           std::tuple{&operation.mesh, &restored, &back}}) {
      const ShapeOrigin& made = to->shape()->origin;
      EXPECT_EQ(made.from.lock(), from->shape());
      EXPECT_EQ(made.faces.size(), to->n_faces());
      SurfaceReplanner taken(*from, {}), matched(*from, {});
      taken.set_topology(*to, *origin);
      matched.set_topology(to->topology(), to->sharpness, *origin);  // a shape of its own: matched
      EXPECT_EQ(taken.last_change().kept, matched.last_change().kept);
      EXPECT_FALSE(taken.last_change().kept.empty());
      test::expect_same_tables(taken.tables(), matched.tables(), name);
      test::expect_same_tables(taken.tables(), build_surface_plans(*to, {}), name);
    }
  }
}

// A change of the Gaussians alone (a transform as an operation: the same faces, sharpness and
// vertices) keeps the tables themselves, every patch kept, under a new id; the same faces with other
// vertices, or a crease, are re-planned.
TEST(IncrementalPlans, TheSameFacesAndVerticesKeepTheTables) {
  for (const char* name : {"pawn", "icosphere"}) {
    CovarianceMesh mesh = make_sample(name);
    SurfaceReplanner replanner(mesh, PlanOptions{});
    const auto tables = replanner.shared_tables();
    const long long id = replanner.last_change().to;
    std::vector<int> itself(mesh.n_vertices());
    for (size_t v = 0; v < itself.size(); ++v) itself[v] = int(v);
    for (const std::vector<int>& origin : {std::vector<int>{}, itself}) {
      const long long before = replanner.last_change().to;
      EXPECT_EQ(replanner.set_topology(mesh, origin), 0) << name;
      EXPECT_EQ(replanner.shared_tables(), tables) << name << ": the same tables, not a copy";
      const PlanChange& change = replanner.last_change();
      EXPECT_EQ(change.from, before) << name;
      EXPECT_GT(change.to, id) << name;
      EXPECT_EQ(change.kept, (std::vector<KeptPatches>{{0, 0, tables->plans.n_patches()}})) << name;
    }
    std::swap(itself[0], itself[1]);  // the same faces, two vertices' Gaussians swapped: read again
    EXPECT_GT(replanner.set_topology(mesh, itself), 0) << name;
    mesh.sharpness.set_crease(mesh.edge(0)[0], mesh.edge(0)[1], 2.0);
    EXPECT_GT(replanner.set_topology(mesh), 0) << name;
    test::expect_same_tables(replanner.tables(), build_surface_plans(mesh.topology(), PlanOptions{}, mesh.sharpness),
                             std::string(name) + " creased");
  }
}

// The faces before those an extrude reaches keep their plans in the whole tables as they were, the
// rows they read included: the four vertices it adds move no row's point index, nor do those its undo
// takes away (the rows start at row_start_for(n_base), which a few vertices more or less leave).
TEST(IncrementalPlans, AnExtrudeLeavesTheTablesBeforeItsFacesAsTheyWere) {
  const CovarianceMesh sphere = make_sample("sphere", 6000);
  SurfaceReplanner replanner(sphere, PlanOptions{});
  const SurfaceTables before = replanner.tables();
  const int f = int(sphere.n_faces() / 2);
  const Modelled extruded = extrude_faces(sphere, {f}, 0.01);
  ASSERT_EQ(row_start_for(int(sphere.n_vertices())), row_start_for(int(extruded.mesh.n_vertices())));
  // The first face that shares a vertex with a face around the extruded one: no plan before it reads
  // a vertex the extrude changed.
  const MeshConnectivity& c = sphere.connectivity();
  int first_reached = f;
  for (const int v : sphere.face(size_t(f)))
    for (int i = c.vertex_face_offsets[size_t(v)]; i < c.vertex_face_offsets[size_t(v) + 1]; ++i)
      for (const int w : sphere.face(size_t(c.vertex_faces[size_t(i)])))
        for (int j = c.vertex_face_offsets[size_t(w)]; j < c.vertex_face_offsets[size_t(w) + 1]; ++j)
          first_reached = std::min(first_reached, c.vertex_faces[size_t(j)]);
  ASSERT_GT(first_reached, 0);
  const auto same_prefix = [&](const SurfaceTables& a, const SurfaceTables& b, const std::string& where) {
    EXPECT_EQ(a.stencils.first_row(), b.stencils.first_row()) << where;
    const size_t nodes = size_t(before.plans.patch_roots[size_t(first_reached)]);
    ASSERT_GE(a.plans.nodes.size(), nodes) << where;
    ASSERT_GE(b.plans.nodes.size(), nodes) << where;
    EXPECT_TRUE(std::equal(a.plans.nodes.begin(), a.plans.nodes.begin() + long(nodes), b.plans.nodes.begin())) << where;
    const size_t corners = 4 * size_t(first_reached);
    EXPECT_TRUE(std::equal(a.plans.patch_corner_points.begin(), a.plans.patch_corner_points.begin() + long(corners),
                           b.plans.patch_corner_points.begin()))
        << where;
  };
  replanner.set_topology(extruded.mesh, extruded.vertex_origin);
  same_prefix(before, replanner.tables(), "extruded");
  test::expect_same_tables(replanner.tables(), build_surface_plans(extruded.mesh.topology(), PlanOptions{}, {}),
                           "extruded");
  replanner.set_topology(sphere, inverse_origin(extruded.vertex_origin, sphere.n_vertices()));
  same_prefix(before, replanner.tables(), "undone");
  test::expect_same_tables(replanner.tables(), before, "undone");
}

// Vertices added past a multiple of kRowStartStep move the rows to the next one: the kept tables follow,
// as a full re-plan numbers them, and so does the undo.
TEST(IncrementalPlans, VerticesAddedPastARowStepMoveEveryRowAsAFullReplanDoes) {
  const CovarianceMesh sphere = make_sample("sphere", 1000);
  const int n = int(sphere.n_vertices());
  ASSERT_LT(n, kRowStartStep);
  std::vector<int> faces;  // faces far apart enough that each extruded one adds its four vertices
  for (int f = 0; f < int(sphere.n_faces()) && n + 4 * int(faces.size()) <= kRowStartStep; f += 37) faces.push_back(f);
  const Modelled extruded = extrude_faces(sphere, faces, 0.01);
  ASSERT_GT(int(extruded.mesh.n_vertices()), kRowStartStep);
  SurfaceReplanner replanner(sphere, PlanOptions{});
  const SurfaceTables before = replanner.tables();
  EXPECT_EQ(before.stencils.first_row(), kRowStartStep);
  replanner.set_topology(extruded.mesh, extruded.vertex_origin);
  EXPECT_EQ(replanner.tables().stencils.first_row(), 2 * kRowStartStep);
  test::expect_same_tables(replanner.tables(), build_surface_plans(extruded.mesh.topology(), PlanOptions{}, {}),
                           "past the step");
  replanner.set_topology(sphere, inverse_origin(extruded.vertex_origin, sphere.n_vertices()));
  test::expect_same_tables(replanner.tables(), before, "undone");
}

// A loop cut around the same sphere crosses every range on its way: it builds again the faces beside
// the loop, not those ranges, and its undo builds as few.
TEST(IncrementalPlans, ALoopCutBuildsTheFacesBesideItsLoopNotTheRangesItCrosses) {
  const CovarianceMesh sphere = make_sample("sphere", 6000);
  PlanOptions options;
  SurfaceReplanner replanner(sphere, options);
  const std::span<const int> face = sphere.face(sphere.n_faces() / 2);
  const Modelled cut = loop_cut(sphere, face[0], face[1], 1);
  const int loop = int(cut.mesh.n_faces() - sphere.n_faces());  // the faces the loop split, each into two
  ASSERT_GT(loop, 100);
  const int planned = replanner.set_topology(cut.mesh, cut.vertex_origin);
  const int undone = replanner.set_topology(sphere, inverse_origin(cut.vertex_origin, sphere.n_vertices()));
  EXPECT_LE(planned, 8 * loop);
  EXPECT_LE(undone, 8 * loop);
  test::expect_same_tables(replanner.tables(), build_surface_plans(sphere.topology(), options, {}), "undone");
}

// Next to the cylinder's octagons, split into quads whose edges meet the side quads as halves beside a
// whole edge: every operation on every face, followed and undone, gives a full re-plan's tables (the
// patch adjacency kept for the patches that stay, linked again beside the ones that change); and each
// face deleted, then its hole filled.
TEST(IncrementalPlans, OperationsBesideSplitFacesMatchAFullReplan) {
  const CovarianceMesh cylinder = make_sample("cylinder");
  PlanOptions options;
  const SurfaceTables cylinder_tables = build_surface_plans(cylinder.topology(), options, {});
  for (int f = 0; f < int(cylinder.n_faces()); ++f) {
    const std::span<const int> c = cylinder.face(size_t(f));
    for (const Modelled& result : {extrude_faces(cylinder, {f}, 0.1), delete_faces(cylinder, {f}),
                                   subdivide_faces(cylinder, {f}), dissolve_edges(cylinder, {{c[0], c[1]}})}) {
      const std::string where = "face " + std::to_string(f) + " (" + result.summary + ")";
      SurfaceReplanner replanner(cylinder.topology(), options, {}, test::kSmallRanges);
      replanner.set_topology(result.mesh.topology(), {}, result.vertex_origin);
      const SurfaceTables full = build_surface_plans(result.mesh.topology(), options, {});
      test::expect_same_tables(replanner.tables(), full, where);
      expect_relinked_named(cylinder_tables, replanner, where);
      replanner.set_topology(cylinder.topology(), {}, inverse_origin(result.vertex_origin, cylinder.n_vertices()));
      test::expect_same_tables(replanner.tables(), cylinder_tables, where + ", undone");
      expect_relinked_named(full, replanner, where + ", undone");
      if (HasFailure()) return;
    }
    // The face deleted, then its hole filled: the patches beside the hole gain a neighbour.
    const CovarianceMesh hole = delete_faces(cylinder, {f}).mesh;
    const Modelled filled = fill(hole, {c.begin(), c.end()});
    SurfaceReplanner replanner(hole.topology(), options, {}, test::kSmallRanges);
    replanner.set_topology(filled.mesh.topology(), {}, filled.vertex_origin);
    test::expect_same_tables(replanner.tables(), build_surface_plans(filled.mesh.topology(), options, {}),
                             "face " + std::to_string(f) + " deleted and filled");
  }
}

// A topology the plans refuse (a crease between unjoined vertices) leaves the tables as they were.
TEST(IncrementalPlans, ARefusedTopologyChangesNothing) {
  const CovarianceMesh grid = test::grid_mesh(3, 3);
  SurfaceReplanner replanner(grid.topology(), {}, {});
  const SurfaceTables before = replanner.tables();
  Sharpness bad;
  bad.set_crease(0, 15, 2.0);
  EXPECT_THROW(replanner.set_topology(grid.topology(), bad), Error);
  test::expect_same_tables(replanner.tables(), before, "after the refusal");
  const Modelled extruded = extrude_faces(grid, {4}, 0.1);
  replanner.set_topology(extruded.mesh.topology(), {}, extruded.vertex_origin);
  test::expect_same_tables(replanner.tables(), build_surface_plans(extruded.mesh.topology(), {}, {}),
                           "after the refusal, an extrude");
}

}  // namespace
}  // namespace gps
