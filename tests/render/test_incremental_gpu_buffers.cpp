// The renderer following a replanner through modelling operations (SurfaceRenderer::set_mesh with a
// PlanChange): the corner pass evaluates only what a change reached and copies the rest, and its
// output and the plan points equal those of a renderer set up anew for the same mesh, bit for bit,
// after random operations of every kind, their undo and their redo, on quad, triangle, mixed, open and
// creased meshes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <random>
#include <type_traits>

#include "core/modelling/extrude.h"
#include "core/modelling/samples.h"
#include "core/plans/patch_adjacency.h"
#include "core/plans/surface_replanner.h"
#include "core/support/error.h"
#include "core/plans/kept_patch_records.h"
#include "render/gl/gpu_layout.h"
#include "render/pipeline/kept_corner_output.h"
#include "render/pipeline/surface_renderer.h"
#include "tests/support/gl_fixture.h"
#include "tests/support/plan_tables.h"
#include "tests/support/random_operations.h"

namespace gps {
namespace {

using IncrementalGpuBuffers = test::GlTest;

// A table's array as its buffer holds it: ints as they are, reals as floats.
template <class T>
std::vector<uint32_t> words_of(const std::vector<T>& values) {
  std::vector<uint32_t> words(values.size());
  for (size_t i = 0; i < values.size(); ++i) {
    if constexpr (std::is_floating_point_v<T>) {
      const float value = float(values[i]);
      std::memcpy(&words[i], &value, sizeof(float));
    } else {
      words[i] = uint32_t(values[i]);
    }
  }
  return words;
}

// Every table buffer holds its array of `renderer`'s tables, bit for bit: the uploads that send only
// what changed sent all of it.
void expect_tables_held(const SurfaceRenderer& renderer, const std::string& where) {
  const SurfaceTables& t = renderer.tables();
  const std::pair<int, std::vector<uint32_t>> arrays[] = {
      {gpu::kBindingOffsets, words_of(t.stencils.offsets)},
      {gpu::kBindingIndices, words_of(t.stencils.indices)},
      {gpu::kBindingWeights, words_of(t.stencils.weights)},
      {gpu::kBindingNodes, words_of(t.plans.nodes)},
      {gpu::kBindingRoots, words_of(t.plans.patch_roots)},
      {gpu::kBindingCorners, words_of(t.plans.patch_corner_points)},
      {gpu::kBindingExtraordinaryTables, words_of(t.plans.extraordinary_tables)},
      {gpu::kBindingPatchEdges, words_of(t.plans.patch_edges)},
      {gpu::kBindingPatchNeighbours, words_of(t.plans.patch_neighbours)},
      {gpu::kBindingCornerOwners, words_of(t.plans.corner_owners)}};
  for (const auto& [binding, words] : arrays) {
    std::vector<uint32_t> held = renderer.read_table_buffer(binding);
    ASSERT_GE(held.size(), words.size()) << where << ": binding " << binding;
    held.resize(words.size());
    const auto wrong = std::mismatch(words.begin(), words.end(), held.begin()).first;
    EXPECT_TRUE(wrong == words.end()) << where << ": binding " << binding << " differs at word "
                                      << (wrong - words.begin()) << " of " << words.size();
  }
}

// `renderer`'s tables as uploaded, its corner-pass output and plan points against a renderer given
// the same tables anew.
void expect_as_set_anew(const SurfaceRenderer& renderer, const CovarianceMesh& mesh, const NormalisedFrame& frame,
                        const std::string& where) {
  expect_tables_held(renderer, where);
  SurfaceRenderer fresh;
  fresh.set_mesh(mesh, renderer.tables(), frame);
  EXPECT_TRUE(renderer.read_corner_pass() == fresh.read_corner_pass()) << where << ": corner pass";
  EXPECT_TRUE(renderer.read_points() == fresh.read_points()) << where << ": plan points";
}

// Corner slots the corner pass evaluated, and all it had, over a run of operations.
struct Evaluated {
  long long evaluated = 0, slots = 0;
};

// Up to `operations` random operations on `mesh` (the first moves two vertices' Gaussians, which keeps
// every plan), each followed, undone and redone by one renderer in one frame, as the bench's meshes
// keep theirs, and checked against a renderer set anew after each. Returns how many applied.
int follow_random_operations(CovarianceMesh mesh, Scheme scheme, int operations, const std::string& name,
                             Evaluated& figures) {
  PlanOptions options;
  options.scheme = scheme;
  const NormalisedFrame frame = NormalisedFrame::of(mesh);
  SurfaceReplanner replanner(mesh.topology(), options, mesh.sharpness, test::kSmallRanges);
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh, replanner.tables(), frame, replanner.last_change(), {});
  std::mt19937 random(5);
  int applied = 0;
  for (int step = 0; step < 40 && applied < operations; ++step) {
    Modelled result;
    try {
      result = step == 0 ? transform_vertices(mesh, {0, 1}, AffineMap::about(mesh.mean(0), 0.7 * Mat3::Identity()))
                         : test::random_operation(mesh, random);
      replanner.set_topology(result.mesh.topology(), result.mesh.sharpness, result.vertex_origin);
    } catch (const Error&) {
      continue;  // refused by the operation or the scheme: nothing to show
    }
    ++applied;
    const std::string where = name + ", step " + std::to_string(step) + " (" + result.summary + ")";
    renderer.set_mesh(result.mesh, replanner.tables(), frame, replanner.last_change(), result.vertex_origin);
    figures.evaluated += renderer.last_corner_slots();
    figures.slots += renderer.tables().plans.corners() * renderer.tables().plans.n_patches();
    expect_as_set_anew(renderer, result.mesh, frame, where);
    const std::vector<int> back = inverse_origin(result.vertex_origin, mesh.n_vertices());
    replanner.set_topology(mesh.topology(), mesh.sharpness, back);
    renderer.set_mesh(mesh, replanner.tables(), frame, replanner.last_change(), back);
    expect_as_set_anew(renderer, mesh, frame, where + ", undone");
    replanner.set_topology(result.mesh.topology(), result.mesh.sharpness, result.vertex_origin);
    renderer.set_mesh(result.mesh, replanner.tables(), frame, replanner.last_change(), result.vertex_origin);
    expect_as_set_anew(renderer, result.mesh, frame, where + ", redone");
    mesh = std::move(result.mesh);
  }
  return applied;
}

TEST_F(IncrementalGpuBuffers, RandomOperationsMatchARendererSetAnew) {
  for (const test::RandomOperationCase& c : test::random_operation_cases()) {
    Evaluated figures;
    EXPECT_GE(follow_random_operations(c.mesh, c.scheme, c.operations / 2, c.name, figures), c.operations / 2 - 2)
        << c.name;
    // On a mesh of a few dozen faces every piece is most of it.
    if (c.mesh.n_faces() > 200) {
      EXPECT_LT(figures.evaluated, figures.slots / 2) << c.name << ": most corners kept their output";
    }
  }
}

// Each kind of operation on a quad, an open creased quad and a creased triangle mesh (where it applies:
// a few tries at random elements), followed and undone by one renderer: as one set anew both ways.
TEST_F(IncrementalGpuBuffers, EveryKindOfOperationMatchesARendererSetAnew) {
  std::vector<int> applied(size_t(test::kOperationKinds), 0);
  std::mt19937 random(3);
  const std::vector<test::RandomOperationCase> cases = test::random_operation_cases();
  for (const size_t i : {size_t(0), size_t(1), size_t(4)}) {
    const test::RandomOperationCase& c = cases[i];
    PlanOptions options;
    options.scheme = c.scheme;
    const NormalisedFrame frame = NormalisedFrame::of(c.mesh);
    SurfaceReplanner replanner(c.mesh.topology(), options, c.mesh.sharpness, test::kSmallRanges);
    SurfaceRenderer renderer;
    renderer.set_mesh(c.mesh, replanner.tables(), frame, replanner.last_change(), {});
    for (int kind = 0; kind < test::kOperationKinds; ++kind)
      for (int attempt = 0; attempt < 6; ++attempt) {
        Modelled result;
        try {
          result = test::operation_of_kind(c.mesh, kind, random);
          replanner.set_topology(result.mesh.topology(), result.mesh.sharpness, result.vertex_origin);
        } catch (const Error&) {
          continue;  // refused by the operation or the scheme
        }
        const std::string where = c.name + ", kind " + std::to_string(kind) + " (" + result.summary + ")";
        renderer.set_mesh(result.mesh, replanner.tables(), frame, replanner.last_change(), result.vertex_origin);
        expect_as_set_anew(renderer, result.mesh, frame, where);
        const std::vector<int> back = inverse_origin(result.vertex_origin, c.mesh.n_vertices());
        replanner.set_topology(c.mesh.topology(), c.mesh.sharpness, back);
        renderer.set_mesh(c.mesh, replanner.tables(), frame, replanner.last_change(), back);
        expect_as_set_anew(renderer, c.mesh, frame, where + ", undone");
        ++applied[size_t(kind)];
        break;
      }
  }
  for (int kind = 0; kind < test::kOperationKinds; ++kind)
    EXPECT_GT(applied[size_t(kind)], 0) << "operation kind " << kind << " applied to none of the meshes";
}

// Past kParallelFaces vertices and patches, the passes that find what a change reached run on all
// cores: the same output as a renderer set anew.
TEST_F(IncrementalGpuBuffers, RandomOperationsOnALargeMeshMatchARendererSetAnew) {
  const CovarianceMesh sphere = make_sample("sphere", 6000);
  ASSERT_GE(sphere.n_vertices(), size_t(kParallelFaces));
  Evaluated figures;
  EXPECT_EQ(follow_random_operations(sphere, Scheme::catmull_clark, 4, "sphere/6000", figures), 4);
  EXPECT_LT(figures.evaluated, figures.slots / 4) << "most corners kept their output";
}

// Gaussians thin enough for double points: the unchanged ones are carried in double, and where a
// change makes the first thin Gaussian (or removes the last) everything is uploaded in the new precision.
TEST_F(IncrementalGpuBuffers, ThinGaussiansAreCarriedInDoublePoints) {
  const Mat3 flat = Vec3(1.0, 1.0, 1e-4).asDiagonal();  // condition 1e8 times the Gaussian's own
  CovarianceMesh thin = make_sample("sphere", 400);
  for (size_t v = 0; v < thin.n_vertices(); ++v) thin.set_covariance(v, flat * thin.covariance(v) * flat);
  CovarianceMesh one_thin = make_sample("sphere", 400);
  one_thin.set_covariance(7, flat * one_thin.covariance(7) * flat);
  {
    SurfaceRenderer renderer;
    renderer.set_mesh(thin, build_surface_plans(thin, {}), NormalisedFrame::of(thin));
    ASSERT_EQ(renderer.point_precision(), PointPrecision::double_float);
  }
  Evaluated figures;
  EXPECT_GE(follow_random_operations(thin, Scheme::catmull_clark, 8, "thin sphere", figures), 6);
  EXPECT_GE(follow_random_operations(one_thin, Scheme::catmull_clark, 8, "sphere with one thin Gaussian", figures), 6);
}

// The kept output is only for the tables the renderer shows: tables it was not given by the replanner
// (a preview of other plans), another frame, or a change from other tables evaluate everything.
TEST_F(IncrementalGpuBuffers, AChangeFromOtherTablesOrFrameEvaluatesEverything) {
  const CovarianceMesh sphere = make_sample("sphere", 1500);
  const NormalisedFrame frame = NormalisedFrame::of(sphere);
  SurfaceReplanner replanner(sphere.topology(), {}, {}, test::kSmallRanges);
  SurfaceRenderer renderer;
  renderer.set_mesh(sphere, replanner.tables(), frame, replanner.last_change(), {});
  const int all = renderer.tables().plans.corners() * renderer.tables().plans.n_patches();
  EXPECT_EQ(renderer.last_corner_slots(), all);

  const Modelled extruded = extrude_faces(sphere, {int(sphere.n_faces() / 2)}, 0.01);
  replanner.set_topology(extruded.mesh.topology(), {}, extruded.vertex_origin);
  renderer.set_mesh(extruded.mesh, replanner.tables(), frame, replanner.last_change(), extruded.vertex_origin);
  EXPECT_GT(renderer.last_corner_slots(), 0);
  EXPECT_LT(renderer.last_corner_slots(), all / 4) << "an extrude of one face";
  expect_as_set_anew(renderer, extruded.mesh, frame, "extruded");

  // Back to the sphere, in another frame: everything.
  const std::vector<int> back = inverse_origin(extruded.vertex_origin, sphere.n_vertices());
  replanner.set_topology(sphere.topology(), {}, back);
  NormalisedFrame moved = frame;
  moved.unit *= 2.0;
  renderer.set_mesh(sphere, replanner.tables(), moved, replanner.last_change(), back);
  EXPECT_EQ(renderer.last_corner_slots(), all);
  expect_as_set_anew(renderer, sphere, moved, "another frame");

  // Shown without the replanner, then a change from the replanner's tables: everything.
  renderer.set_mesh(sphere, build_surface_plans(sphere.topology(), {}, {}), moved);
  replanner.set_topology(extruded.mesh.topology(), {}, extruded.vertex_origin);
  renderer.set_mesh(extruded.mesh, replanner.tables(), moved, replanner.last_change(), extruded.vertex_origin);
  const int all_extruded = renderer.tables().plans.corners() * renderer.tables().plans.n_patches();
  EXPECT_EQ(renderer.last_corner_slots(), all_extruded);
  expect_as_set_anew(renderer, extruded.mesh, moved, "from other tables");
}

// An extrude past the bounding box moves the mesh's own frame a little; the renderer's frame, followed
// (NormalisedFrame::following), stays, and so does the output the extrude did not reach. A mesh moved
// far off gets its own frame.
TEST_F(IncrementalGpuBuffers, AnExtrudePastTheBoundingBoxKeepsTheFrameAndTheOutput) {
  const CovarianceMesh sphere = make_sample("sphere", 1500);
  SurfaceReplanner replanner(sphere.topology(), {}, {}, test::kSmallRanges);
  SurfaceRenderer renderer;
  renderer.set_mesh(sphere, replanner.tables(), NormalisedFrame::of(sphere), replanner.last_change(), {});
  int top = 0;  // the face whose centre is highest
  double highest = -1e9;
  for (int f = 0; f < int(sphere.n_faces()); ++f) {
    double y = 0.0;
    for (const int v : sphere.face(size_t(f))) y += sphere.mean(size_t(v)).y();
    if (y > highest) highest = y, top = f;
  }
  const Modelled extruded = extrude_faces(sphere, {top}, 0.1);
  ASSERT_FALSE(NormalisedFrame::of(extruded.mesh) == renderer.frame()) << "the bounding box grew";
  const NormalisedFrame frame = renderer.frame().following(extruded.mesh);
  EXPECT_TRUE(frame == renderer.frame());
  replanner.set_topology(extruded.mesh.topology(), {}, extruded.vertex_origin);
  renderer.set_mesh(extruded.mesh, replanner.tables(), frame, replanner.last_change(), extruded.vertex_origin);
  const int all = renderer.tables().plans.corners() * renderer.tables().plans.n_patches();
  EXPECT_LT(renderer.last_corner_slots(), all / 4);
  expect_as_set_anew(renderer, extruded.mesh, frame, "extruded past the box");

  const Modelled moved = transform_vertices(sphere, {}, AffineMap{Mat3::Identity(), Vec3(5.0, 0.0, 0.0)});
  EXPECT_TRUE(renderer.frame().following(moved.mesh) == NormalisedFrame::of(moved.mesh));
}

// An extrude that also changes the Gaussian of a vertex far from it, on a creased mesh: the stencil
// rows the replanner kept are carried over but those that read that vertex, computed again.
TEST_F(IncrementalGpuBuffers, KeptRowsThatReadAChangedVertexAreComputedAgain) {
  CovarianceMesh mesh = make_sample("sphere", 1500);
  for (size_t e = 0; e < mesh.n_edges(); e += 7) mesh.sharpness.set_crease(mesh.edge(e)[0], mesh.edge(e)[1], 2.0);
  SurfaceReplanner replanner(mesh, {}, test::kSmallRanges);
  SurfaceRenderer renderer;
  const NormalisedFrame frame = NormalisedFrame::of(mesh);
  renderer.set_mesh(mesh, replanner.tables(), frame, replanner.last_change(), {});
  Modelled extruded = extrude_faces(mesh, {0}, 0.05);
  const int far = int(mesh.n_vertices()) - 1;  // read by crease rows far from face 0
  const std::vector<int> rows = rows_reading(stencil_dependents(replanner.tables().stencils), {far});
  ASSERT_FALSE(rows.empty()) << "stencil rows read the vertex";
  const int moved = extruded.vertex_origin.empty()
                        ? far
                        : int(std::find(extruded.vertex_origin.begin(), extruded.vertex_origin.end(), far) -
                              extruded.vertex_origin.begin());
  ASSERT_LT(size_t(moved), extruded.mesh.n_vertices());
  extruded.mesh.set_mean(size_t(moved), extruded.mesh.mean(size_t(moved)) * 1.01);
  replanner.set_topology(extruded.mesh, extruded.vertex_origin);
  ASSERT_FALSE(replanner.last_change().kept_rows.empty()) << "rows kept";
  renderer.set_mesh(extruded.mesh, replanner.tables(), frame, replanner.last_change(), extruded.vertex_origin);
  expect_as_set_anew(renderer, extruded.mesh, frame, "extruded, a far vertex moved");
}

// A crease dragged (SurfaceReplanner::set_sharpness, as the crease tool re-plans) evaluates only the
// corners of the faces it reached, and matches a renderer set anew; the first crease of a mesh and the
// removal of its last re-plan, and evaluate, everything.
TEST_F(IncrementalGpuBuffers, ACreaseChangeEvaluatesOnlyTheFacesItReached) {
  CovarianceMesh mesh = make_sample("sphere", 1500);
  const NormalisedFrame frame = NormalisedFrame::of(mesh);
  mesh.sharpness.set_crease(0, 1, 1.0);
  SurfaceReplanner replanner(mesh.topology(), {}, mesh.sharpness, test::kSmallRanges);
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh, replanner.tables(), frame, replanner.last_change(), {});
  const int all = renderer.tables().plans.corners() * renderer.tables().plans.n_patches();
  for (const double sharpness : {2.0, 3.5, kInfiniteSharpness, 0.5}) {
    mesh.sharpness.set_crease(0, 1, sharpness);
    replanner.set_sharpness(mesh.sharpness);
    const ReplannedTables replanned = replanner.replanned();
    renderer.set_mesh(mesh, replanned.tables, frame, replanned.change, {});
    EXPECT_LT(renderer.last_corner_slots(), all / 4) << "sharpness " << sharpness;
    expect_as_set_anew(renderer, mesh, frame, "sharpness " + std::to_string(sharpness));
  }
  mesh.sharpness = {};  // the last crease gone: every plan
  replanner.set_sharpness(mesh.sharpness);
  renderer.set_mesh(mesh, replanner.tables(), frame, replanner.last_change(), {});
  EXPECT_EQ(renderer.last_corner_slots(), all);
  expect_as_set_anew(renderer, mesh, frame, "no crease");
}

// A kept patch whose corner another patch now owns is evaluated again, and its slot there, which it no
// longer evaluates, holds zero as in a renderer set anew (not the value it kept). The tables are the
// grid's with the owner of patch 0's corner 2 (a lowest index rule would give patch 0) moved to patch 4.
TEST_F(IncrementalGpuBuffers, AKeptPatchWhoseCornerChangesOwnerIsEvaluatedAgain) {
  const CovarianceMesh grid = test::grid_mesh(3, 3);
  const SurfaceTables before = build_surface_plans(grid.topology(), {}, {});
  SurfaceTables after = before;
  std::vector<int32_t>& owners = after.plans.corner_owners;
  const int n = after.plans.corners();
  int patch4_corner = -1;
  for (int c = 0; c < n; ++c)
    if (owners[size_t(2 * (n * 4 + c))] == 0 && (owners[size_t(2 * (n * 4 + c)) + 1] & kOwnerCornerMask) == 2)
      patch4_corner = c;
  ASSERT_GE(patch4_corner, 0) << "patch 4 shares patch 0's corner 2";
  for (size_t slot = 0; 2 * slot < owners.size(); ++slot)
    if (owners[2 * slot] == 0 && (owners[2 * slot + 1] & kOwnerCornerMask) == 2)
      owners[2 * slot] = 4, owners[2 * slot + 1] = patch4_corner;
  const std::vector<char> evaluate = patches_not_kept_alike(before.plans, after.plans, {{0, 0, 9}});
  for (int p = 0; p < 9; ++p)
    EXPECT_EQ(evaluate[size_t(p)] != 0, p == 0 || p == 1 || p == 3 || p == 4) << "patch " << p;

  const NormalisedFrame frame = NormalisedFrame::of(grid);
  constexpr long long kShown = 1LL << 60;  // ids no replanner gives in this test
  SurfaceRenderer renderer;
  renderer.set_mesh(grid, before, frame, {0, kShown, {}, std::nullopt, {}}, {});
  renderer.set_mesh(grid, after, frame, {kShown, kShown + 1, {{0, 0, 9}}, std::nullopt, {}}, {});
  EXPECT_LT(renderer.last_corner_slots(), 9 * n) << "patches 0, 1, 3 and 4 and their corners' owners";
  expect_as_set_anew(renderer, grid, frame, "owner moved");
}

// Kept runs fit where they lie inside both tables and increase in both numberings.
TEST(KeptCornerOutput, RunsFitInsideBothTablesInOrder) {
  EXPECT_TRUE(kept_runs_fit({}, 0, 0));
  EXPECT_TRUE(kept_runs_fit({{0, 0, 4}, {6, 4, 2}}, 6, 8));
  EXPECT_FALSE(kept_runs_fit({{0, 0, 4}, {6, 4, 2}}, 5, 8)) << "past the previous tables";
  EXPECT_FALSE(kept_runs_fit({{0, 0, 4}, {6, 4, 3}}, 8, 8)) << "past the new tables";
  EXPECT_FALSE(kept_runs_fit({{4, 0, 2}, {0, 2, 2}}, 8, 8)) << "out of order";
  EXPECT_FALSE(kept_runs_fit({{0, 0, 0}}, 8, 8)) << "an empty run";
}

}  // namespace
}  // namespace gps
