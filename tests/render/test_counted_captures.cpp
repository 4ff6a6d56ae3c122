// Captures made from the patches' triangle counts (render/cache/surface_cache.h): the same stored
// triangles and frames as captures that query each block.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "core/modelling/samples.h"
#include "render/cache/surface_cache.h"
#include "render/gl/render_target.h"
#include "render/pipeline/surface_renderer.h"
#include "tests/support/cache_frames.h"
#include "tests/support/gl_fixture.h"

namespace gps {
namespace {

using namespace test;  // the cache tests' frames (tests/support/cache_frames.h)

// Each test with the stored vertices welded at each capture (as on a GPU), by the first frame that
// draws them unchanged (as on llvmpipe), and never.
class CountedCaptures : public test::GlTest, public ::testing::WithParamInterface<SurfaceCache::Weld> {};

constexpr int kSize = 160;

// A capture after one made block by block, once the patches' counts agreed with its queries, takes
// the counts and captures every block in one draw: the same stored triangles and the same frame as a
// capture that queries each block, on quads with boundaries and extraordinary vertices, a mixed
// mesh, Loop's triangles and creases, at uniform and adaptive levels.
TEST_P(CountedCaptures, StoreWhatBlockByBlockCapturesStore) {
  RenderTarget counted_target(kSize, kSize), queried_target(kSize, kSize);
  CovarianceMesh creased = make_sample("sphere", 600);
  for (int v = 0; v + 1 < 40; ++v)
    if (const int e = creased.find_edge(v, v + 1); e >= 0) creased.sharpness.creases.push_back({v, v + 1, 2.0});
  creased.sharpness.normalise();
  const std::vector<std::pair<std::string, CovarianceMesh>> meshes = {{"grid", make_sample("grid", 400)},
                                                                      {"pawn", make_sample("pawn")},
                                                                      {"icosphere", make_sample("icosphere", 320)},
                                                                      {"creased sphere", creased}};
  for (const auto& [name, mesh] : meshes)
    for (const DrawOptions& o : {uniform(3), uniform(4.5f), adaptive(4), adaptive(12)}) {
      const std::string what = name + (o.pixels > 0 ? " adaptive " + std::to_string(int(o.pixels)) + " px"
                                                    : " level " + std::to_string(o.level));
      SurfaceRenderer counted, queried;
      for (SurfaceRenderer* r : {&counted, &queried}) {
        r->surface_cache().set_weld(GetParam());
        r->set_mesh(mesh);
      }
      queried.surface_cache().set_counted_captures(false);
      Camera camera = frame_mesh(mesh, 35.0f, 25.0f);
      for (int k = 0; k < 3; ++k) {
        const Frame a = draw(counted, counted_target, camera, o, true);
        const Frame b = draw(queried, queried_target, camera, o, true);
        ASSERT_EQ(counted.surface_cache().captures(), k + 1) << what;
        EXPECT_EQ(counted.surface_cache().last_capture_counted(), k > 0) << what << ", capture " << k;
        EXPECT_FALSE(queried.surface_cache().last_capture_counted()) << what;
        EXPECT_EQ(differing_pixels(a, b), 0u) << what << ", capture " << k;
        EXPECT_TRUE(
            same_triangles(counted.surface_cache().stored_triangles(), queried.surface_cache().stored_triangles()))
            << what << ", capture " << k;
        // The blocks lie where their counts say: an edit's refresh captures its blocks into place.
        CovarianceMesh edited = mesh;
        const int v = int(mesh.n_vertices()) / 3;
        move_vertex(edited, v, 0.02);
        for (SurfaceRenderer* r : {&counted, &queried}) r->update_vertices(edited, {v});
        const Frame c = draw(counted, counted_target, camera, o, true);
        EXPECT_EQ(differing_pixels(c, draw(queried, queried_target, camera, o, true)), 0u) << what << ", edit " << k;
        EXPECT_EQ(counted.surface_cache().captures(), k + 1) << what << ", edit " << k;
        EXPECT_TRUE(
            same_triangles(counted.surface_cache().stored_triangles(), queried.surface_cache().stored_triangles()))
            << what << ", edit " << k;
        // Captured again under another camera: by the camera at adaptive levels where it moves beyond
        // the hysteresis, and by the mesh given again (a file opened).
        camera = frame_mesh(mesh, 35.0f + 50.0f * float(k + 1), 25.0f - 20.0f * float(k + 1));
        camera.distance *= k == 0 ? 0.6f : 1.0f;
        for (SurfaceRenderer* r : {&counted, &queried}) r->set_mesh(mesh);
      }
    }
}

INSTANTIATE_TEST_SUITE_P(StoredVertices, CountedCaptures, test::kWeldModes, test::weld_mode_name);

}  // namespace
}  // namespace gps
