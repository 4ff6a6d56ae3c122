// The surface cache: frames drawn from the stored triangles against the live pipeline,
// invalidation by edits and levels, and the adaptive levels' camera hysteresis.
#include "render/cache/surface_cache.h"

#include <glad/gl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "core/modelling/samples.h"
#include "render/gl/device_memory.h"
#include "render/gl/gl_context.h"
#include "render/gl/render_target.h"
#include "render/pipeline/surface_renderer.h"
#include "tests/support/device_limits.h"
#include "tests/support/cache_frames.h"
#include "tests/support/gl_fixture.h"

namespace gps {
namespace {

using namespace test;  // the cache tests' frames (tests/support/cache_frames.h)

// Each test with the stored vertices welded at each capture (as on a GPU), by the first frame that
// draws them unchanged (as on llvmpipe), and never.
class SurfaceCacheTest : public test::GlTest, public ::testing::WithParamInterface<SurfaceCache::Weld> {
protected:
  bool welds() const { return GetParam() != SurfaceCache::Weld::off; }
};

constexpr int kSize = 160;

// A cached frame against the live one. The stored triangles are the live pipeline's own vertices,
// but llvmpipe projects a vertex stage's output in that stage's code and a tessellation stage's
// output apart from it, and the two round differently: covered pixels and node kinds are the
// same, colours within 2/255 (the MatCap lookup), and the interpolated position and normal AOVs
// within 1e-3 of the surface's size and of a unit normal.
::testing::AssertionResult same_surface(const Frame& cached, const Frame& live) {
  const Image &normal_a = cached.layers[2], &normal_b = live.layers[2];
  if (normal_a.pixels.size() != normal_b.pixels.size())
    return ::testing::AssertionFailure() << "frames of different sizes";
  float size = 0.0f;
  for (size_t i = 0; i < live.layers[1].pixels.size(); i += 4)
    if (normal_b.pixels[i + 3] != 0.0f)
      for (size_t k = 0; k < 3; ++k) size = std::max(size, std::abs(live.layers[1].pixels[i + k]));
  const float tolerance[3] = {2.0f / 255.0f, 1e-3f * size, 1e-3f};
  const char* layer_name[3] = {"colour", "position", "normal"};
  for (size_t i = 0; i < normal_a.pixels.size(); i += 4) {
    const size_t pixel = i / 4;
    if (normal_a.pixels[i + 3] != normal_b.pixels[i + 3])
      return ::testing::AssertionFailure() << "pixel " << pixel << ": coverage or node kind " << normal_a.pixels[i + 3]
                                           << " against " << normal_b.pixels[i + 3];
    for (int l = 0; l < 3; ++l)
      for (size_t k = 0; k < 3; ++k) {
        const float d = std::abs(cached.layers[l].pixels[i + k] - live.layers[l].pixels[i + k]);
        if (!(d <= tolerance[l]))
          return ::testing::AssertionFailure() << "pixel " << pixel << ": " << layer_name[l] << " differs by " << d
                                               << " (tolerance " << tolerance[l] << ")";
      }
  }
  return ::testing::AssertionSuccess();
}

TEST_P(SurfaceCacheTest, CachedFramesEqualLiveFrames) {
  RenderTarget target(kSize, kSize);
  for (const char* name : {"cube", "pawn", "icosphere", "cone-pointy"}) {
    const CovarianceMesh mesh = make_sample(name);
    SurfaceRenderer renderer;
    renderer.surface_cache().set_weld(GetParam());
    renderer.set_mesh(mesh);
    const Camera camera = frame_mesh(mesh, 35.0f, 25.0f), turned = frame_mesh(mesh, -60.0f, 10.0f);
    for (DrawOptions o : {uniform(1), uniform(5), adaptive(6)}) {
      for (const bool wireframe : {false, true}) {
        o.wireframe = wireframe;
        const std::string what = std::string(name) +
                                 (o.pixels > 0 ? " adaptive" : " level " + std::to_string(int(o.level))) +
                                 (wireframe ? " wireframe" : "");
        const Frame live = draw(renderer, target, camera, o, false);
        const int before = renderer.surface_cache().captures();
        const Frame first = draw(renderer, target, camera, o, true);  // drawn as it is captured
        const Frame second = draw(renderer, target, camera, o, true);
        EXPECT_TRUE(renderer.surface_cache().has_stored_triangles()) << what;
        // A wireframe is shading only: the stored triangles serve it.
        EXPECT_EQ(renderer.surface_cache().captures(), before + (wireframe ? 0 : 1)) << what;
        EXPECT_TRUE(same_surface(first, live)) << what;
        EXPECT_TRUE(same_surface(second, live)) << what;
        if (o.pixels > 0) continue;
        // Uniform levels do not depend on the camera: the stored triangles seen from elsewhere.
        const Frame live_turned = draw(renderer, target, turned, o, false);
        const Frame cached_turned = draw(renderer, target, turned, o, true);
        EXPECT_EQ(renderer.surface_cache().captures(), before + (wireframe ? 0 : 1)) << what;
        EXPECT_TRUE(same_surface(cached_turned, live_turned)) << what << ", turned";
      }
    }
  }
}

// Where nothing is stored, an adaptive capture sizes its buffer by counting the triangles first
// (SurfaceRenderer::capture_cache); later ones take the last count, and close up the patches make
// more: the full buffer grows and the capture takes every triangle, as the live frame draws them.
TEST_P(SurfaceCacheTest, AdaptiveCapturesHoldWhatTheyDrawAndGrowWhenTheyNeedMore) {
  RenderTarget target(kSize, kSize);
  const CovarianceMesh mesh = make_sample("pawn");
  SurfaceRenderer renderer;
  renderer.surface_cache().set_weld(GetParam());
  renderer.set_mesh(mesh);
  renderer.set_collect_statistics(true);
  const DrawOptions o = adaptive(2);
  long long drawn_before = 0;
  for (const float closer : {1.0f, 0.2f}) {
    Camera camera = frame_mesh(mesh, 35.0f, 25.0f);
    camera.distance *= closer;
    const Frame live = draw(renderer, target, camera, o, false);
    glFinish();
    const long long drawn = renderer.last_statistics().triangles;
    const Frame first = draw(renderer, target, camera, o, true);
    EXPECT_TRUE(renderer.surface_cache().has_stored_triangles());
    EXPECT_EQ(renderer.surface_cache().triangles(), drawn);
    // Unwelded, the buffer is all there is: the count and an eighth, below 1.2 times the triangles' bytes.
    const double held = double(renderer.surface_cache().buffer_bytes()) / double(drawn * SurfaceCache::kTriangleBytes);
    std::printf("distance x%.1f: %lld triangles, the buffers hold %.2f times their bytes\n", closer, drawn, held);
    if (!welds() && closer == 1.0f) {
      EXPECT_LT(held, 1.2);
    }
    EXPECT_TRUE(same_surface(first, live)) << closer;
    EXPECT_TRUE(same_surface(draw(renderer, target, camera, o, true), live)) << closer;
    if (closer < 1.0f) {
      ASSERT_GT(drawn, 2 * drawn_before) << "the case of this test: more than the last capture's buffer";
    }
    drawn_before = drawn;
  }
  EXPECT_EQ(renderer.surface_cache().captures(), 2);
}

// Welded, each point of the surface is fetched once, as the floor's welded buffer has it: the
// triangles of a patch share its grid points, and the patches (in one block or not) share the
// points of their edges and corners. An edit's refresh (level 4: its blocks captured and welded
// again; level 8: their welded vertices evaluated again) keeps as many. Welded when settled, the
// frame that captures draws the triangles as captured, and the next one welded.
TEST_P(SurfaceCacheTest, WeldedVerticesAreEachSurfacePointOnce) {
  RenderTarget target(kSize, kSize);
  const CovarianceMesh cube = make_sample("cube");
  SurfaceRenderer renderer;
  renderer.surface_cache().set_weld(GetParam());
  renderer.set_mesh(cube);
  SurfaceCache& cache = renderer.surface_cache();
  const bool settles = GetParam() == SurfaceCache::Weld::when_settled;
  for (const int level : {1, 8}) {
    const Camera camera = frame_mesh(cube, 35.0f, 25.0f);
    draw(renderer, target, camera, uniform(float(level)), true);
    const long long patches = renderer.tables().plans.n_patches();
    ASSERT_EQ(cache.triangles(), patches * 2 * level * level);
    // The cube's surface points at level L: inside its 6 faces, on its 12 edges, its 8 corners.
    const long long points = 6 * (level - 1) * (level - 1) + 12 * (level - 1) + 8;
    EXPECT_EQ(cache.stored_vertices_welded(), welds() && !settles);
    EXPECT_EQ(cache.distinct_vertices(), welds() && !settles ? points : 3 * cache.triangles()) << "level " << level;
    draw(renderer, target, camera, uniform(float(level)), true);
    EXPECT_EQ(cache.stored_vertices_welded(), welds());
    EXPECT_EQ(cache.distinct_vertices(), welds() ? points : 3 * cache.triangles()) << "level " << level;
    EXPECT_EQ(cache.stored_triangles().positions.size(), size_t(points)) << "the floor's welded vertices";
  }
  // Level 4: the edit's blocks captured again (and welded again) where the weld waits for a still
  // frame, else evaluated again; level 8: evaluated again.
  for (const float level : {4.0f, 8.0f}) {
    CovarianceMesh sphere = make_sample("sphere", 3000);
    renderer.set_mesh(sphere);
    const Camera camera = frame_mesh(sphere, 35.0f, 25.0f);
    draw(renderer, target, camera, uniform(level), true);
    draw(renderer, target, camera, uniform(level), true);
    const long long distinct = cache.distinct_vertices();
    if (welds()) {  // each surface point once, as the floor's welded buffer has it
      EXPECT_EQ(distinct, (long long)cache.stored_triangles().positions.size()) << level;
    }
    const int v = int(sphere.n_vertices() / 2);
    move_vertex(sphere, v, 0.05);
    const int refreshes = cache.refreshes();
    renderer.update_vertices(sphere, {v});
    draw(renderer, target, camera, uniform(level), true);
    EXPECT_EQ(cache.refreshes(), refreshes + 1);
    EXPECT_EQ(cache.stored_vertices_welded(), welds() && (!settles || level >= cache.evaluated_from_level())) << level;
    const Frame settled = draw(renderer, target, camera, uniform(level), true);
    EXPECT_EQ(cache.refreshes(), refreshes + 1);
    EXPECT_EQ(cache.distinct_vertices(), distinct) << level;
    EXPECT_TRUE(same_surface(settled, draw(renderer, target, camera, uniform(level), false))) << level;
  }
}

// An edit that keeps the tessellation (uniform levels from 8; adaptive levels where the level check
// finds a block's patches' levels unchanged) evaluates the welded vertices again
// (render/cache/stored_vertex_evaluation.h) where the tessellation stage evaluated them at the capture:
// the stored triangles are what a capture of the edited points stores, bit for bit (patch edges and
// corners included, which both sides must keep alike), for quad patches with half-size ones (the
// pawn) and Loop's triangles. At uniform levels an edit of every vertex too, with the work groups
// per dispatch lowered to 64 (several dispatches); level 2 where the weld is at capture (more welded
// vertices than a third of the slots). At adaptive ones a covariance scaled (levels kept) and
// vertices moved (some blocks' levels change: captured again beside the evaluated ones).
TEST_P(SurfaceCacheTest, EditsEvaluatedAgainEqualACapture) {
  if (!welds()) GTEST_SKIP() << "edits are captured again without a weld";
  RenderTarget target(kSize, kSize);
  std::vector<DrawOptions> settings = {uniform(8), adaptive(4)};
  if (GetParam() == SurfaceCache::Weld::at_capture) settings.push_back(uniform(2));
  for (const DrawOptions& o : settings) {
    int evaluated = 0, captured_again = 0;  // patches, over the edits
    // At adaptive levels not the cube: both moved corners border most of its patches, so that an edit
    // which changes the level of an edge there (every edge of the cube is as long) changes over half
    // of them, which are captured again whole.
    const std::vector<const char*> names = o.pixels > 0 ? std::vector<const char*>{"pawn", "icosphere"}
                                                        : std::vector<const char*>{"pawn", "icosphere", "cube"};
    for (const char* name : names) {
      CovarianceMesh mesh = make_sample(name);
      SurfaceRenderer renderer;
      renderer.surface_cache().set_weld(GetParam());
      renderer.set_mesh(mesh);
      SurfaceCache& cache = renderer.surface_cache();
      const Camera camera = frame_mesh(mesh, 35.0f, 25.0f);
      const int n = int(mesh.n_vertices());
      std::vector<int> every(static_cast<size_t>(n));
      for (int v = 0; v < n; ++v) every[size_t(v)] = v;
      const std::vector<std::vector<int>> edits = o.pixels > 0 ? std::vector<std::vector<int>>{{n / 2}, {n / 2, n / 3}}
                                                               : std::vector<std::vector<int>>{{n / 2, n / 3}, every};
      for (size_t e = 0; e < edits.size(); ++e) {
        const std::vector<int>& edited = edits[e];
        const std::string what = std::string(name) +
                                 (o.pixels > 0 ? " adaptive" : " level " + std::to_string(int(o.level))) + ", edit " +
                                 std::to_string(e);
        if (edited.size() > 2) DeviceLimitsForTests::lower(renderer, 64, 0);
        draw(renderer, target, camera, o, true);
        draw(renderer, target, camera, o, true);  // settled
        const int captures = cache.captures(), refreshes = cache.refreshes();
        for (const int v : edited) {
          if (o.pixels > 0 && e == 0)
            mesh.set_covariance(size_t(v), mesh.covariance(size_t(v)) * 1.1);
          else
            move_vertex(mesh, v, (o.pixels > 0 ? 0.02 : 0.2) / double(edited.size()));
        }
        renderer.update_vertices(mesh, edited);
        draw(renderer, target, camera, o, true);
        ASSERT_EQ(cache.captures(), captures) << what;
        ASSERT_EQ(cache.refreshes(), refreshes + 1) << what;
        evaluated += cache.evaluated_patches();
        captured_again += cache.refreshed_patches() - cache.evaluated_patches();
        if (o.pixels <= 0) {
          EXPECT_EQ(cache.evaluated_patches(), cache.refreshed_patches()) << what;
        }
        const TriangleMesh refreshed = cache.stored_triangles();
        draw(renderer, target, camera, uniform(3), true);
        draw(renderer, target, camera, o, true);  // the same points captured
        ASSERT_EQ(cache.captures(), captures + 2) << what;
        EXPECT_TRUE(same_triangles(refreshed, cache.stored_triangles())) << what;
      }
    }
    EXPECT_GT(evaluated, 0);
    if (o.pixels > 0) {
      EXPECT_GT(captured_again, 0) << "no edit changed adaptive levels";
    }
    std::printf("%s: %d patches evaluated again, %d captured again\n",
                o.pixels > 0 ? "adaptive" : ("level " + std::to_string(int(o.level))).c_str(), evaluated,
                captured_again);
  }
}

// A drag's frames leave the captured copies of the vertices they evaluated as they were
// (render/cache/surface_cache.h); what reads those copies brings them up to date first: a frame of the
// quads' grid, a refresh that captures blocks again (adaptive levels: the move changes some), the
// read-back. Three edits without a still frame between, the last one's frame with the grid: the
// same frame, and the same stored triangles, as after a capture of the same points.
TEST_P(SurfaceCacheTest, ADragsEvaluatedVerticesReachTheGridAndTheReadBack) {
  if (!welds()) GTEST_SKIP() << "edits are captured again without a weld";
  RenderTarget target(kSize, kSize);
  for (const DrawOptions& o : {uniform(8), adaptive(4)}) {
    const std::string what = o.pixels > 0 ? "adaptive" : "level 8";
    CovarianceMesh mesh = make_sample("pawn");
    SurfaceRenderer renderer;
    renderer.surface_cache().set_weld(GetParam());
    renderer.set_mesh(mesh);
    SurfaceCache& cache = renderer.surface_cache();
    const Camera camera = frame_mesh(mesh, 35.0f, 25.0f);
    DrawOptions grid = o;
    grid.wireframe = true;
    draw(renderer, target, camera, o, true);
    draw(renderer, target, camera, o, true);  // settled
    const int captures = cache.captures(), n = int(mesh.n_vertices());
    int evaluated = 0, captured_again = 0;
    Frame dragged;
    for (const int v : {n / 2, n / 3, n / 5}) {
      if (v == n / 3)
        move_vertex(mesh, v, 0.02);
      else
        mesh.set_covariance(size_t(v), mesh.covariance(size_t(v)) * 1.1);
      renderer.update_vertices(mesh, {v});
      dragged = draw(renderer, target, camera, v == n / 5 ? grid : o, true);
      evaluated += cache.evaluated_patches();
      captured_again += cache.refreshed_patches() - cache.evaluated_patches();
    }
    ASSERT_EQ(cache.captures(), captures) << what;
    EXPECT_GT(evaluated, 0) << what;
    if (o.pixels > 0) {
      EXPECT_GT(captured_again, 0) << "no move changed adaptive levels";
    }
    const TriangleMesh stored = cache.stored_triangles();
    draw(renderer, target, camera, uniform(3), true);
    draw(renderer, target, camera, o, true);  // the same points captured
    ASSERT_EQ(cache.captures(), captures + 2) << what;
    EXPECT_EQ(differing_pixels(dragged, draw(renderer, target, camera, grid, true)), 0u) << what;
    EXPECT_TRUE(same_triangles(stored, cache.stored_triangles())) << what;
  }
}

TEST_P(SurfaceCacheTest, AnEditShowsInTheNextFrame) {
  RenderTarget target(kSize, kSize);
  CovarianceMesh mesh = make_sample("pawn");
  SurfaceRenderer renderer;
  renderer.surface_cache().set_weld(GetParam());
  renderer.set_mesh(mesh);
  const Camera camera = frame_mesh(mesh, 35.0f, 25.0f);
  const DrawOptions o = uniform(4);
  const Frame before = draw(renderer, target, camera, o, true);
  EXPECT_EQ(renderer.surface_cache().captures(), 1);
  const int v = int(mesh.n_vertices() / 2);
  mesh.set_mean(size_t(v),
                mesh.mean(size_t(v)) + 0.3 * bounding_box_diagonal(mesh) * Vec3(1.0, 0.5, 0.25).normalized());
  renderer.update_vertices(mesh, {v});
  const Frame edited = draw(renderer, target, camera, o, true);
  // A one-vertex edit captures the blocks of its patches again, not the whole surface.
  EXPECT_EQ(renderer.surface_cache().captures(), 1);
  EXPECT_EQ(renderer.surface_cache().refreshes(), 1);
  EXPECT_GT(differing_pixels(before, edited), 20u);
  EXPECT_TRUE(same_surface(edited, draw(renderer, target, camera, o, false)));
  // recompute_all and a level change capture everything; the same inputs again do not.
  renderer.recompute_all();
  draw(renderer, target, camera, o, true);
  EXPECT_EQ(renderer.surface_cache().captures(), 2);
  draw(renderer, target, camera, uniform(5), true);
  EXPECT_EQ(renderer.surface_cache().captures(), 3);
  draw(renderer, target, camera, uniform(5), true);
  EXPECT_EQ(renderer.surface_cache().captures(), 3);
  // set_mesh: a new mesh, captured anew.
  renderer.set_mesh(make_sample("cube"));
  draw(renderer, target, camera, uniform(5), true);
  EXPECT_EQ(renderer.surface_cache().captures(), 4);
  EXPECT_EQ(renderer.surface_cache().refreshes(), 1);
}

TEST_P(SurfaceCacheTest, AdaptiveLevelsRecaptureOnlyBeyondTheHysteresis) {
  RenderTarget target(kSize, kSize);
  const CovarianceMesh mesh = make_sample("cube");
  SurfaceRenderer renderer;
  renderer.surface_cache().set_weld(GetParam());
  renderer.set_mesh(mesh);
  const DrawOptions o = adaptive(4);
  Camera camera = frame_mesh(mesh, 35.0f, 25.0f);
  draw(renderer, target, camera, o, true);
  EXPECT_EQ(renderer.surface_cache().captures(), 1);
  const float distance = camera.distance;
  camera.distance = distance * 1.1f;  // edges ~9% shorter on screen: within the factor 1.25
  draw(renderer, target, camera, o, true);
  EXPECT_EQ(renderer.surface_cache().captures(), 1);
  camera.distance = distance * 0.9f;
  draw(renderer, target, camera, o, true);
  EXPECT_EQ(renderer.surface_cache().captures(), 1);
  camera.distance = distance * 0.6f;  // ~1.7× longer: captured again, and equal to the live frame
  const Frame near = draw(renderer, target, camera, o, true);
  EXPECT_EQ(renderer.surface_cache().captures(), 2);
  EXPECT_TRUE(same_surface(near, draw(renderer, target, camera, o, false)));
  // A turn that foreshortens edges beyond the factor captures too.
  Camera turned = frame_mesh(mesh, 80.0f, 60.0f);
  turned.distance = camera.distance;
  draw(renderer, target, turned, o, true);
  EXPECT_EQ(renderer.surface_cache().captures(), 3);
  // A tighter factor: the small move now counts.
  renderer.surface_cache().set_hysteresis(1.01f);
  turned.distance *= 1.1f;
  draw(renderer, target, turned, o, true);
  EXPECT_EQ(renderer.surface_cache().captures(), 4);
  // A different target edge length is a different key.
  draw(renderer, target, turned, adaptive(8), true);
  EXPECT_EQ(renderer.surface_cache().captures(), 5);
}

// The memory limit follows the device's memory (on llvmpipe the machine's, which is always known).
using SurfaceCacheLimit = test::GlTest;

TEST_F(SurfaceCacheLimit, IsAShareOfTheDevicesMemory) {
  const long long device = device_memory_bytes();
  if (software_renderer()) {
    EXPECT_GT(device, 1ll << 30) << "the machine's physical memory";
  }
  const SurfaceCache cache;
  EXPECT_EQ(cache.limit_bytes(), std::clamp(device / SurfaceCache::kDeviceMemoryShare, SurfaceCache::kLeastLimitBytes,
                                            SurfaceCache::kMostLimitBytes));
}

TEST_P(SurfaceCacheTest, PastTheMemoryLimitFramesAreDrawnLive) {
  RenderTarget target(kSize, kSize);
  const CovarianceMesh mesh = make_sample("cube");
  SurfaceRenderer renderer;
  renderer.surface_cache().set_weld(GetParam());
  renderer.set_mesh(mesh);
  renderer.surface_cache().set_limit_bytes(100 * SurfaceCache::kTriangleBytes);  // 100 triangles
  const Camera camera = frame_mesh(mesh);
  const DrawOptions o = uniform(8);
  const Frame cached = draw(renderer, target, camera, o, true);
  EXPECT_FALSE(renderer.surface_cache().has_stored_triangles());
  EXPECT_TRUE(same_surface(cached, draw(renderer, target, camera, o, false)));
  draw(renderer, target, camera, o, true);  // refused inputs are not tried again every frame
  EXPECT_EQ(renderer.surface_cache().captures(), 1);
  // Nor after an edit, which leaves the count the same: drawn live, the edit shown.
  CovarianceMesh edited = mesh;
  move_vertex(edited, 3, 0.2);
  renderer.update_vertices(edited, {3});
  const Frame after_edit = draw(renderer, target, camera, o, true);
  EXPECT_EQ(renderer.surface_cache().captures(), 1);
  EXPECT_FALSE(same_surface(after_edit, cached));
  EXPECT_TRUE(same_surface(after_edit, draw(renderer, target, camera, o, false)));
  // Small enough (level 1: 2 triangles per patch, from an estimate past the limit) it fits.
  draw(renderer, target, camera, uniform(1), true);
  EXPECT_TRUE(renderer.surface_cache().has_stored_triangles());
  EXPECT_EQ(renderer.surface_cache().triangles(), 2 * renderer.tables().plans.n_patches());
  EXPECT_EQ(renderer.surface_cache().stored_vertices_welded(), welds() && GetParam() == SurfaceCache::Weld::at_capture);
  // Level 2 fits as captured, but welded would take more than the limit: drawn as captured, still frames too.
  draw(renderer, target, camera, uniform(2), true);
  EXPECT_TRUE(renderer.surface_cache().has_stored_triangles());
  ASSERT_GT(renderer.surface_cache().triangles() * SurfaceCache::kWeldedTriangleBytes,
            100 * SurfaceCache::kTriangleBytes);
  const Frame still = draw(renderer, target, camera, uniform(2), true);
  EXPECT_FALSE(renderer.surface_cache().stored_vertices_welded());
  EXPECT_EQ(renderer.surface_cache().distinct_vertices(), 3 * renderer.surface_cache().triangles());
  EXPECT_TRUE(same_surface(still, draw(renderer, target, camera, uniform(2), false)));
}

TEST_P(SurfaceCacheTest, EditedFramesEqualLiveFrames) {
  RenderTarget target(kSize, kSize);
  for (const char* name : {"cube", "pawn", "icosphere"}) {
    for (const DrawOptions& o : {uniform(4), uniform(8), adaptive(6)}) {
      const std::string what =
          std::string(name) + (o.pixels > 0 ? " adaptive" : " level " + std::to_string(int(o.level)));
      CovarianceMesh mesh = make_sample(name);
      SurfaceRenderer renderer;
      renderer.surface_cache().set_weld(GetParam());
      renderer.set_mesh(mesh);
      const Camera camera = frame_mesh(mesh, 35.0f, 25.0f);
      draw(renderer, target, camera, o, true);
      draw(renderer, target, camera, o, true);  // a still frame: welded when settled too
      const int n = int(mesh.n_vertices());
      const long long triangles = renderer.surface_cache().triangles();
      for (const std::vector<int>& edited : {std::vector<int>{n / 2}, std::vector<int>{n / 3, n / 3 + 1, 2 * n / 3}}) {
        for (const int v : edited) move_vertex(mesh, v, 0.2);
        renderer.update_vertices(mesh, edited);
        const Frame cached = draw(renderer, target, camera, o, true);
        EXPECT_TRUE(same_surface(cached, draw(renderer, target, camera, o, false)))
            << what << ", " << edited.size() << " vertices";
      }
      // The cube's every patch reads every vertex: captured whole, unless its welded vertices are
      // evaluated again (uniform levels from evaluated_from_level()). The others: only the edits' blocks.
      const bool partial = std::string(name) != "cube" ||
                           (welds() && o.pixels <= 0 && o.level >= renderer.surface_cache().evaluated_from_level());
      EXPECT_EQ(renderer.surface_cache().captures(), partial ? 1 : 3) << what;
      EXPECT_EQ(renderer.surface_cache().refreshes(), partial ? 2 : 0) << what;
      // Uniform levels keep every block's count; adaptive ones here change some (a new buffer is assembled).
      if (o.pixels <= 0) {
        EXPECT_EQ(renderer.surface_cache().triangles(), triangles) << what;
      } else if (partial) {
        EXPECT_NE(renderer.surface_cache().triangles(), triangles) << what;
      }
    }
  }
}

TEST_P(SurfaceCacheTest, AOneVertexEditCapturesOnlyTheBlocksOfItsPatches) {
  RenderTarget target(kSize, kSize);
  CovarianceMesh mesh = make_sample("sphere", 3000);
  SurfaceRenderer renderer;
  renderer.surface_cache().set_weld(GetParam());
  renderer.set_mesh(mesh);
  const Camera camera = frame_mesh(mesh, 35.0f, 25.0f);
  const DrawOptions o = uniform(3);
  draw(renderer, target, camera, o, true);
  const int v = int(mesh.n_vertices() / 2);
  move_vertex(mesh, v, 0.05);
  renderer.update_vertices(mesh, {v});
  const Frame cached = draw(renderer, target, camera, o, true);
  SurfaceCache& cache = renderer.surface_cache();
  EXPECT_EQ(cache.captures(), 1);
  EXPECT_EQ(cache.refreshes(), 1);
  EXPECT_GT(cache.refreshed_patches(), 0);
  EXPECT_LT(4 * cache.refreshed_patches(), renderer.tables().plans.n_patches());
  EXPECT_TRUE(same_surface(cached, draw(renderer, target, camera, o, false)));
}

TEST_P(SurfaceCacheTest, EditsAndUndoEqualLiveFramesEachTime) {
  RenderTarget target(kSize, kSize);
  for (const DrawOptions& o : {uniform(3), adaptive(5)}) {
    const CovarianceMesh original = make_sample("pawn");
    CovarianceMesh mesh = original;
    SurfaceRenderer renderer;
    renderer.surface_cache().set_weld(GetParam());
    renderer.set_mesh(mesh);
    const Camera camera = frame_mesh(mesh, 35.0f, 25.0f);
    draw(renderer, target, camera, o, true);  // drawn as it is captured
    const Frame first = draw(renderer, target, camera, o, true);
    const int n = int(mesh.n_vertices());
    // Moves, a covariance scaled, then each undone (the values before it back), newest first.
    const std::vector<std::vector<int>> edits = {{n / 2}, {n / 2 + 1, n / 4}, {n / 5}, {n / 2}};
    std::vector<CovarianceMesh> before;
    for (size_t e = 0; e < edits.size(); ++e) {
      before.push_back(mesh);
      for (const int v : edits[e]) {
        if (e == 2)
          mesh.covariances[size_t(v)] *= 1.5;
        else
          move_vertex(mesh, v, 0.1);
      }
      renderer.update_vertices(mesh, edits[e]);
      EXPECT_TRUE(same_surface(draw(renderer, target, camera, o, true), draw(renderer, target, camera, o, false)))
          << "edit " << e;
    }
    for (size_t e = edits.size(); e-- > 0;) {
      for (const int v : edits[e]) {
        mesh.set_mean(size_t(v), before[e].mean(size_t(v)));
        mesh.covariances[size_t(v)] = before[e].covariances[size_t(v)];
      }
      renderer.update_vertices(mesh, edits[e]);
      EXPECT_TRUE(same_surface(draw(renderer, target, camera, o, true), draw(renderer, target, camera, o, false)))
          << "undo " << e;
    }
    EXPECT_EQ(differing_pixels(draw(renderer, target, camera, o, true), first), 0u);  // both from the cache
    EXPECT_EQ(renderer.surface_cache().captures(), 1);
    EXPECT_EQ(renderer.surface_cache().refreshes(), int(2 * edits.size()));
  }
}

TEST_P(SurfaceCacheTest, AnEditAfterASmallCameraMoveKeepsTheLevelsOfTheCapture) {
  RenderTarget target(kSize, kSize);
  CovarianceMesh mesh = make_sample("pawn");
  SurfaceRenderer renderer;
  renderer.surface_cache().set_weld(GetParam());
  renderer.set_mesh(mesh);
  const DrawOptions o = adaptive(5);
  const Camera camera = frame_mesh(mesh, 35.0f, 25.0f);
  Camera moved = camera;
  moved.distance *= 1.1f;  // within the hysteresis: no capture
  draw(renderer, target, camera, o, true);
  draw(renderer, target, moved, o, true);
  const int v = int(mesh.n_vertices() / 2);
  move_vertex(mesh, v, 0.1);
  renderer.update_vertices(mesh, {v});
  draw(renderer, target, moved, o, true);  // refreshed with the capture's levels
  EXPECT_EQ(renderer.surface_cache().captures(), 1);
  EXPECT_EQ(renderer.surface_cache().refreshes(), 1);
  EXPECT_TRUE(same_surface(draw(renderer, target, camera, o, true), draw(renderer, target, camera, o, false)));
}

// Welded when settled with a delay (an editor's pause): the frames before it draw the stored triangles
// as captured, repeat none, and equal the live ones; the first still frame past it (and not the first
// still frame) welds them all. The
// blocks an edit captures again are welded by its next still frame, the delay or not; a new mesh waits
// again.
class SurfaceCacheWeldDelay : public test::GlTest {};

TEST_F(SurfaceCacheWeldDelay, AWholeWeldWaitsForThePauseAndAPartialOneDoesNot) {
  RenderTarget target(kSize, kSize);
  CovarianceMesh sphere = make_sample("sphere", 3000);
  SurfaceRenderer renderer;
  SurfaceCache& cache = renderer.surface_cache();
  cache.set_weld(SurfaceCache::Weld::when_settled);
  cache.set_whole_weld_delay(std::chrono::hours(1));
  renderer.set_mesh(sphere);
  const Camera camera = frame_mesh(sphere, 35.0f, 25.0f);
  const DrawOptions o = uniform(4.0f);
  for (int frame = 0; frame < 3; ++frame) {
    const Frame cached = draw(renderer, target, camera, o, true);
    EXPECT_FALSE(cache.stored_vertices_welded()) << frame;
    EXPECT_FALSE(cache.settled()) << frame;
    EXPECT_FALSE(renderer.draws_as_last(target, camera, o)) << frame << ": the frames go on until the weld";
    EXPECT_TRUE(same_surface(cached, draw(renderer, target, camera, o, false))) << frame;
  }
  EXPECT_EQ(cache.distinct_vertices(), 3 * cache.triangles());
  cache.set_whole_weld_delay(std::chrono::milliseconds(20));
  std::this_thread::sleep_for(std::chrono::milliseconds(40));
  draw(renderer, target, camera, o, true);
  EXPECT_TRUE(cache.stored_vertices_welded());
  EXPECT_TRUE(cache.settled());
  const long long distinct = cache.distinct_vertices();
  EXPECT_LT(distinct, 3 * cache.triangles());

  cache.set_whole_weld_delay(std::chrono::hours(1));
  const int v = int(sphere.n_vertices() / 2);
  move_vertex(sphere, v, 0.05);
  renderer.update_vertices(sphere, {v});
  draw(renderer, target, camera, o, true);  // its blocks captured again, welded when settled
  const Frame settled = draw(renderer, target, camera, o, true);
  EXPECT_TRUE(cache.stored_vertices_welded());
  EXPECT_EQ(cache.distinct_vertices(), distinct);
  EXPECT_TRUE(same_surface(settled, draw(renderer, target, camera, o, false)));

  renderer.set_mesh(make_sample("sphere", 2000));
  draw(renderer, target, camera, o, true);
  draw(renderer, target, camera, o, true);
  EXPECT_FALSE(cache.stored_vertices_welded());
  // Past the delay, the first still frame still does not weld (a frame of a large mesh outlasts it);
  // the second does.
  cache.set_whole_weld_delay(std::chrono::milliseconds(1));
  renderer.set_mesh(make_sample("sphere", 3000));
  draw(renderer, target, camera, o, true);
  std::this_thread::sleep_for(std::chrono::milliseconds(10));
  draw(renderer, target, camera, o, true);
  EXPECT_FALSE(cache.stored_vertices_welded());
  draw(renderer, target, camera, o, true);
  EXPECT_TRUE(cache.stored_vertices_welded());
}

INSTANTIATE_TEST_SUITE_P(StoredVertices, SurfaceCacheTest, test::kWeldModes, test::weld_mode_name);

}  // namespace
}  // namespace gps
