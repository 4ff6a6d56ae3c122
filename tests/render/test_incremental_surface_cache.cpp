// The surface cache following a change of topology (SurfaceCache::topology_changed): after random
// operations of every kind, their undo and their redo, the captured vertices equal those of a renderer
// set up anew and captured under the same camera, bit for bit; an operation that keeps most patches
// (an extrude, a delete) captures only the blocks it reached, not the whole surface.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <set>

#include "core/modelling/affine_transform.h"
#include "core/modelling/delete_elements.h"
#include "core/modelling/extrude.h"
#include "core/modelling/loop_cut.h"
#include "core/modelling/samples.h"
#include "core/plans/surface_replanner.h"
#include "core/support/error.h"
#include "render/gl/render_target.h"
#include "render/pipeline/surface_renderer.h"
#include "tests/support/gl_fixture.h"
#include "tests/support/plan_tables.h"
#include "tests/support/random_operations.h"
#include "view/camera.h"

namespace gps {
namespace {

class IncrementalSurfaceCache : public test::GlTest, public ::testing::WithParamInterface<SurfaceCache::Weld> {};
using IncrementalSurfaceCacheRandom = test::GlTest;

constexpr int kSize = 128;

DrawOptions cached(float pixels, float level) {
  DrawOptions o;
  o.surface_cache = true;
  o.pixels = pixels;
  o.level = level;
  return o;
}

// `renderer`'s stored triangles after a frame against those of a renderer given the same tables anew
// and drawn once with the same camera and options.
void expect_as_captured_anew(SurfaceRenderer& renderer, const CovarianceMesh& mesh, const NormalisedFrame& frame,
                             const RenderTarget& target, const Camera& camera, const DrawOptions& o,
                             const std::string& where) {
  renderer.draw(target, camera, o);
  SurfaceRenderer fresh;
  fresh.surface_cache().set_weld(renderer.surface_cache().weld_mode());
  fresh.set_mesh(mesh, renderer.tables(), frame);
  fresh.draw(target, camera, o);
  // Every float of every captured vertex: position, normal and kind, grid, and the patch it was
  // evaluated at, which an edit evaluates it at again and the weld keys it by.
  const std::vector<float> followed = renderer.surface_cache().captured_vertices(),
                           anew = fresh.surface_cache().captured_vertices();
  EXPECT_GT(anew.size(), 0u) << where;
  EXPECT_TRUE(followed.size() == anew.size() &&
              std::memcmp(followed.data(), anew.data(), anew.size() * sizeof(float)) == 0)
      << where << ": " << followed.size() / 36 << " triangles followed, " << anew.size() / 36 << " anew";
}

// Each mesh with another way of welding (at capture, when settled, never), in turn.
TEST_F(IncrementalSurfaceCacheRandom, RandomOperationsMatchAFreshCapture) {
  RenderTarget target(kSize, kSize);
  const SurfaceCache::Weld welds[] = {SurfaceCache::Weld::at_capture, SurfaceCache::Weld::when_settled,
                                      SurfaceCache::Weld::off};
  int weld = 0, refreshes = 0;
  for (const test::RandomOperationCase& c : test::random_operation_cases()) {
    PlanOptions options;
    options.scheme = c.scheme;
    CovarianceMesh mesh = c.mesh;
    const NormalisedFrame frame = NormalisedFrame::of(mesh);
    const Camera camera = frame_mesh(mesh, 35.0f, 25.0f);
    SurfaceReplanner replanner(mesh.topology(), options, mesh.sharpness, test::kSmallRanges);
    SurfaceRenderer renderer;
    renderer.surface_cache().set_weld(welds[weld++ % 3]);
    renderer.set_mesh(mesh, replanner.tables(), frame, replanner.last_change(), {});
    std::mt19937 random(11);
    int applied = 0;
    for (int step = 0; step < 30 && applied < c.operations / 3; ++step) {
      // Adaptive levels, and a uniform level the welded vertices are evaluated at.
      const DrawOptions o = step % 2 == 0 ? cached(6.0f, 0.0f) : cached(0.0f, 8.0f);
      renderer.draw(target, camera, o);  // a capture (or a refresh) to follow from
      Modelled result;
      try {
        result = test::random_operation(mesh, random);
        replanner.set_topology(result.mesh.topology(), result.mesh.sharpness, result.vertex_origin);
      } catch (const Error&) {
        continue;
      }
      ++applied;
      const std::string where = c.name + ", step " + std::to_string(step) + " (" + result.summary + ")";
      renderer.set_mesh(result.mesh, replanner.tables(), frame, replanner.last_change(), result.vertex_origin);
      expect_as_captured_anew(renderer, result.mesh, frame, target, camera, o, where);
      const std::vector<int> back = inverse_origin(result.vertex_origin, mesh.n_vertices());
      replanner.set_topology(mesh.topology(), mesh.sharpness, back);
      renderer.set_mesh(mesh, replanner.tables(), frame, replanner.last_change(), back);
      expect_as_captured_anew(renderer, mesh, frame, target, camera, o, where + ", undone");
      replanner.set_topology(result.mesh.topology(), result.mesh.sharpness, result.vertex_origin);
      renderer.set_mesh(result.mesh, replanner.tables(), frame, replanner.last_change(), result.vertex_origin);
      expect_as_captured_anew(renderer, result.mesh, frame, target, camera, o, where + ", redone");
      mesh = std::move(result.mesh);
    }
    EXPECT_GE(applied, c.operations / 3 - 1) << c.name;
    refreshes += renderer.surface_cache().refreshes();
  }
  // The small meshes' changes reach over half their patches, which are captured again whole.
  EXPECT_GE(refreshes, 6) << "changes followed, not only captured again";
}

// The cache locates a kept patch's triangles inside its block by the counts the levels give
// (render/cache/patch_triangle_counts.h): on every kind of mesh (quads, half-size patches of split
// faces, Loop's triangles), at uniform levels of each parity, and at adaptive levels from 1 to many a
// side, mismatched edges included, each patch's count is what the tessellator generates of it alone.
TEST_F(IncrementalSurfaceCacheRandom, PatchTriangleCountsAreWhatTheTessellatorGenerates) {
  const int width = 256, height = 192;
  std::vector<DrawOptions> options;
  for (const float level : {1.0f, 2.0f, 3.0f, 4.5f, 7.0f}) options.push_back(cached(0.0f, level));
  for (const float pixels : {3.0f, 8.0f, 20.0f, 400.0f}) options.push_back(cached(pixels, 0.0f));
  options.push_back(cached(6.0f, 0.0f));
  options.back().diagnostics.mismatched_edge_levels = true;
  for (const test::RandomOperationCase& c : test::random_operation_cases()) {
    PlanOptions plan;
    plan.scheme = c.scheme;
    const SurfaceReplanner replanner(c.mesh.topology(), plan, c.mesh.sharpness);
    SurfaceRenderer renderer;
    renderer.set_mesh(c.mesh, replanner.tables(), NormalisedFrame::of(c.mesh), replanner.last_change(), {});
    const Camera camera = frame_mesh(c.mesh, 35.0f, 25.0f);
    const int n_patches = renderer.tables().plans.n_patches();
    std::set<int> adaptive_counts;
    for (const DrawOptions& o : options) {
      const std::vector<int> counts = renderer.patch_triangle_counts(camera, o, width, height);
      ASSERT_EQ(counts.size(), size_t(n_patches)) << c.name;
      int differing = 0, first = -1;
      for (int p = 0; p < n_patches; ++p) {
        const size_t generated = renderer.capture_vertices(camera, o, width, height, p, 1).size() / 3;
        if (o.pixels > 0.0f) adaptive_counts.insert(counts[size_t(p)]);
        if (size_t(counts[size_t(p)]) != generated && differing++ == 0) first = p;
      }
      EXPECT_EQ(differing, 0) << c.name << ", level " << o.level << ", pixels " << o.pixels << ": patch " << first
                              << " and " << differing - 1 << " more";
    }
    EXPECT_GE(adaptive_counts.size(), 6u) << c.name << ": patches at many levels";
  }
}

// A sphere of `faces` faces drawn by a renderer that welds as `weld` says, its plans from a replanner
// of ranges of `faces_per_range` faces, framed and seen as the tests below see it.
struct SphereScene {
  SphereScene(int faces, SurfaceCache::Weld weld, int faces_per_range = SurfaceReplanner::kFacesPerRange)
      : sphere(make_sample("sphere", faces)),
        frame(NormalisedFrame::of(sphere)),
        camera(frame_mesh(sphere, 35.0f, 25.0f)),
        replanner(sphere.topology(), {}, {}, faces_per_range) {
    renderer.surface_cache().set_weld(weld);
    renderer.set_mesh(sphere, replanner.tables(), frame, replanner.last_change(), {});
  }
  // The renderer and replanner follow `mesh`, whose vertices came from `origin`.
  void follow(const CovarianceMesh& mesh, const std::vector<int>& origin) {
    replanner.set_topology(mesh.topology(), {}, origin);
    renderer.set_mesh(mesh, replanner.tables(), frame, replanner.last_change(), origin);
  }

  const CovarianceMesh sphere;
  const NormalisedFrame frame;
  const Camera camera;
  SurfaceReplanner replanner;
  SurfaceRenderer renderer;
};

// An extrude of one face of a sphere keeps every other patch's number, and a delete of one face
// renumbers the patches after it: the frame after either refreshes the blocks it reached instead of
// capturing the surface again, and so does its undo. (Reached: the patches of the faces the
// replanner planned again, here in small ranges, and their neighbours.)
TEST_P(IncrementalSurfaceCache, AnExtrudeOrADeleteCapturesOnlyTheBlocksItReached) {
  RenderTarget target(kSize, kSize);
  SphereScene scene(6000, GetParam(), test::kSmallRanges);
  auto& [sphere, frame, camera, replanner, renderer] = scene;
  const int f = int(sphere.n_faces() / 3);
  const Modelled results[] = {extrude_faces(sphere, {f}, 0.05), delete_faces(sphere, {f})};
  for (const DrawOptions& o : {cached(6.0f, 0.0f), cached(0.0f, 4.0f)})
    for (const Modelled& result : results) {
      renderer.draw(target, camera, o);
      const SurfaceCache& cache = renderer.surface_cache();
      const int captures = cache.captures(), refreshes = cache.refreshes();
      scene.follow(result.mesh, result.vertex_origin);
      expect_as_captured_anew(renderer, result.mesh, frame, target, camera, o, result.summary);
      EXPECT_EQ(cache.captures(), captures) << result.summary << ": no capture of the whole surface";
      EXPECT_EQ(cache.refreshes(), refreshes + 1) << result.summary;
      EXPECT_LT(cache.refreshed_patches(), renderer.tables().plans.n_patches() / 10) << result.summary;
      const std::vector<int> back = inverse_origin(result.vertex_origin, sphere.n_vertices());
      scene.follow(sphere, back);
      expect_as_captured_anew(renderer, sphere, frame, target, camera, o, result.summary + ", undone");
      EXPECT_EQ(cache.captures(), captures) << result.summary;
      EXPECT_EQ(cache.refreshes(), refreshes + 2) << result.summary;
    }
}

// A loop cut around the sphere changes a ring of faces spread over the whole face numbering: the
// kept patches come in hundreds of runs, and a block cannot follow patches that two runs move apart.
// A block kept with some of its patches changed is split where its kept ends' triangles lie, found
// from their levels (SurfaceCache::check_patch_triangles), and only the patches between are captured
// again: fewer than where the cache is told that the counts cannot be trusted.
TEST_P(IncrementalSurfaceCache, ALoopCutAroundTheMeshCapturesFewerThanHalfItsPatches) {
  RenderTarget target(kSize, kSize);
  int refreshed[2] = {0, 0};
  for (const bool counts_trusted : {true, false}) {
    SphereScene scene(20000, GetParam());
    auto& [sphere, frame, camera, replanner, renderer] = scene;
    const std::span<const int> face = sphere.face(sphere.n_faces() / 2);
    const Modelled result = loop_cut(sphere, face[0], face[1]);
    const DrawOptions o = cached(6.0f, 0.0f);
    renderer.draw(target, camera, o);
    SurfaceCache& cache = renderer.surface_cache();
    if (!counts_trusted) cache.check_patch_triangles({});
    const int captures = cache.captures();
    replanner.set_topology(result.mesh.topology(), {}, result.vertex_origin);
    ASSERT_GT(replanner.last_change().kept.size(), 20u) << "the ring's faces spread over the numbering";
    renderer.set_mesh(result.mesh, replanner.tables(), frame, replanner.last_change(), result.vertex_origin);
    expect_as_captured_anew(renderer, result.mesh, frame, target, camera, o, result.summary);
    EXPECT_EQ(cache.captures(), captures) << result.summary << ": no capture of the whole surface";
    EXPECT_LT(cache.refreshed_patches(), renderer.tables().plans.n_patches() / 2) << result.summary;
    refreshed[counts_trusted ? 0 : 1] = cache.refreshed_patches();
  }
  EXPECT_LT(refreshed[0], refreshed[1] * 9 / 10) << "blocks split at their kept ends";
}

// Blocks split by one change of topology after another join their neighbours again where they fit
// in a block of the usual size: operations and their undo, over and over, neither fragment the
// blocks nor capture more each time.
TEST_P(IncrementalSurfaceCache, SplitBlocksJoinAgainOverManyOperations) {
  RenderTarget target(kSize, kSize);
  SphereScene scene(20000, GetParam());
  auto& [sphere, frame, camera, replanner, renderer] = scene;
  const DrawOptions o = cached(6.0f, 0.0f);
  renderer.draw(target, camera, o);
  const SurfaceCache& cache = renderer.surface_cache();
  const int captures = cache.captures(), blocks = cache.blocks();
  for (int round = 0; round < 6; ++round) {
    const int f = int(sphere.n_faces() / 7) * (1 + round % 3);
    const std::span<const int> face = sphere.face(size_t(f));
    const Modelled result = round % 2 == 0 ? loop_cut(sphere, face[0], face[1]) : extrude_faces(sphere, {f}, 0.02);
    scene.follow(result.mesh, result.vertex_origin);
    renderer.draw(target, camera, o);
    EXPECT_EQ(cache.captures(), captures) << result.summary << ", round " << round;
    scene.follow(sphere, inverse_origin(result.vertex_origin, sphere.n_vertices()));
    renderer.draw(target, camera, o);
    EXPECT_LE(cache.blocks(), blocks + blocks / 10) << result.summary << ", round " << round;
  }
  EXPECT_EQ(cache.captures(), captures) << "every change followed";
  expect_as_captured_anew(renderer, sphere, frame, target, camera, o, "after the rounds");
}

// An operation that moves every vertex and keeps the faces (a transform of the whole mesh; one that is a
// rotation, uniform scale and translation alone moves the frame instead, test_moved_frame.cpp) changes the
// Gaussians alone: the renderer follows it as an edit of every vertex. Welded at capture (a GPU's
// way), the welded vertices are evaluated again and nothing is captured again.
TEST_P(IncrementalSurfaceCache, AnOperationOnTheGaussiansAloneIsFollowedAsAnEdit) {
  const bool evaluated_again = GetParam() == SurfaceCache::Weld::at_capture;
  RenderTarget target(kSize, kSize);
  SphereScene scene(6000, GetParam(), test::kSmallRanges);
  auto& [sphere, frame, camera, replanner, renderer] = scene;
  const Modelled results[] = {
      transform_vertices(sphere, {}, AffineMap::about(Vec3::Zero(), Vec3(0.98, 0.98, 0.99).asDiagonal())),
      transform_vertices(sphere, {0, 1, 2}, AffineMap{Mat3::Identity(), Vec3(0.0, 0.0, 0.01)})};
  const DrawOptions o = cached(0.0f, 4.0f);
  for (const Modelled& result : results) {
    renderer.draw(target, camera, o);
    renderer.draw(target, camera, o);  // settled: welded on llvmpipe's terms too
    const SurfaceCache& cache = renderer.surface_cache();
    const int captures = cache.captures();
    scene.follow(result.mesh, result.vertex_origin);
    expect_as_captured_anew(renderer, result.mesh, frame, target, camera, o, result.summary);
    if (evaluated_again) {
      EXPECT_EQ(cache.captures(), captures) << result.summary << ": no capture of the whole surface";
    }
    scene.follow(sphere, {});
    renderer.draw(target, camera, o);
    expect_as_captured_anew(renderer, sphere, frame, target, camera, o, result.summary + ", undone");
    if (evaluated_again) {
      EXPECT_EQ(cache.captures(), captures) << result.summary << ", undone";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Welds, IncrementalSurfaceCache,
                         ::testing::Values(SurfaceCache::Weld::at_capture, SurfaceCache::Weld::when_settled,
                                           SurfaceCache::Weld::off),
                         [](const ::testing::TestParamInfo<SurfaceCache::Weld>& info) {
                           return info.param == SurfaceCache::Weld::at_capture     ? std::string("AtCapture")
                                  : info.param == SurfaceCache::Weld::when_settled ? std::string("WhenSettled")
                                                                                   : std::string("Off");
                         });

}  // namespace
}  // namespace gps
