// A frame that would draw what its target already holds (SurfaceRenderer::draws_as_last): the editor
// then keeps the target and draws only its UI. Said only when nothing the draw reads has changed,
// and a kept frame is what drawing it again gives, bit for bit.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "core/modelling/samples.h"
#include "core/evaluation/triangle_mesh.h"
#include "render/gl/render_target.h"
#include "render/image/matcap.h"
#include "render/pipeline/surface_renderer.h"
#include "tests/support/gl_fixture.h"
#include "view/camera.h"

namespace gps {
namespace {

using RepeatedFrames = test::GlTest;

constexpr int kWidth = 96, kHeight = 72;

// Draws until the renderer says the next frame repeats the last (a capture, then a frame from the
// cache); false where it never does within a few frames.
bool draw_until_repeated(SurfaceRenderer& renderer, const RenderTarget& target, const Camera& camera,
                         const DrawOptions& o) {
  for (int frame = 0; frame < 4; ++frame) {
    if (renderer.draws_as_last(target, camera, o)) return true;
    renderer.draw(target, camera, o);
  }
  return renderer.draws_as_last(target, camera, o);
}

TEST_F(RepeatedFrames, ADrawRepeatsOnlyWhenNothingItReadsChanged) {
  const CovarianceMesh cube = make_sample("cube");
  SurfaceRenderer renderer;
  renderer.set_mesh(cube);
  RenderTarget target(kWidth, kHeight), other(kWidth, kHeight);
  const Camera camera = frame_mesh(cube);
  DrawOptions o;
  o.pixels = 6.0f;
  EXPECT_FALSE(renderer.draws_as_last(target, camera, o)) << "nothing drawn yet";
  renderer.draw(target, camera, o);
  EXPECT_FALSE(renderer.draws_as_last(target, camera, o)) << "a frame drawn as captured is followed by a cached one";
  ASSERT_TRUE(draw_until_repeated(renderer, target, camera, o));
  EXPECT_FALSE(renderer.draws_as_last(other, camera, o)) << "another target of the same size";

  // Each change of the camera or of an option, then back: only the frame as drawn repeats.
  Camera turned = camera;
  turned.yaw_degrees += 1.0f;
  EXPECT_FALSE(renderer.draws_as_last(target, turned, o));
  Camera far_target = camera;
  far_target.target.x += 1e-9;
  EXPECT_FALSE(renderer.draws_as_last(target, far_target, o));
  Camera ortho = camera;
  ortho.orthographic = true;
  EXPECT_FALSE(renderer.draws_as_last(target, ortho, o));
  const std::vector<std::pair<std::string, std::function<void(DrawOptions&)>>> changes = {
      {"level", [](DrawOptions& d) { d.level += 1.0f; }},
      {"pixels", [](DrawOptions& d) { d.pixels = 4.0f; }},
      {"mode", [](DrawOptions& d) { d.mode = ShadingMode::normals; }},
      {"wireframe", [](DrawOptions& d) { d.wireframe = true; }},
      {"mesh lines", [](DrawOptions& d) { d.mesh_lines = true; }},
      {"ellipsoids", [](DrawOptions& d) { d.ellipsoids = true; }},
      {"sigma", [](DrawOptions& d) { d.sigma_scale = 2.0f; }},
      {"background", [](DrawOptions& d) { d.background.g = 0.5f; }},
      {"static triangles", [](DrawOptions& d) { d.static_triangles = true; }},
      {"surface cache", [](DrawOptions& d) { d.surface_cache = false; }},
      {"back faces", [](DrawOptions& d) { d.diagnostics.back_faces_magenta = true; }},
      {"edge levels", [](DrawOptions& d) { d.diagnostics.mismatched_edge_levels = true; }},
  };
  for (const auto& [name, change] : changes) {
    DrawOptions changed = o;
    change(changed);
    EXPECT_FALSE(renderer.draws_as_last(target, camera, changed)) << name;
  }
  EXPECT_TRUE(renderer.draws_as_last(target, camera, o));

  // The lists an option points to are compared by what they hold.
  const std::vector<int> ellipsoids = {0, 3}, patches = {1};
  DrawOptions listed = o;
  listed.ellipsoids = true;
  listed.ellipsoid_vertices = &ellipsoids;
  listed.hidden_patches = &patches;
  EXPECT_FALSE(renderer.draws_as_last(target, camera, listed));
  ASSERT_TRUE(draw_until_repeated(renderer, target, camera, listed)) << "drawn live with hidden patches";
  std::vector<int> same_ellipsoids = ellipsoids, same_patches = patches;
  listed.ellipsoid_vertices = &same_ellipsoids;
  listed.hidden_patches = &same_patches;
  EXPECT_TRUE(renderer.draws_as_last(target, camera, listed)) << "other lists holding the same";
  same_ellipsoids.push_back(5);
  EXPECT_FALSE(renderer.draws_as_last(target, camera, listed));
  same_ellipsoids.pop_back();
  same_patches[0] = 2;
  EXPECT_FALSE(renderer.draws_as_last(target, camera, listed));
  same_patches[0] = 1;
  EXPECT_TRUE(renderer.draws_as_last(target, camera, listed));
  const std::vector<char> no_edges(cube.n_edges(), 0);
  listed.hidden_edges = &no_edges;
  EXPECT_FALSE(renderer.draws_as_last(target, camera, listed)) << "a list set where none was";

  // Every change of what the renderer draws.
  ASSERT_TRUE(draw_until_repeated(renderer, target, camera, o));
  CovarianceMesh moved = cube;
  moved.set_mean(0, cube.mean(0) * 1.01);
  renderer.update_vertices(moved, {0});
  EXPECT_FALSE(renderer.draws_as_last(target, camera, o)) << "an edit";
  ASSERT_TRUE(draw_until_repeated(renderer, target, camera, o));
  renderer.set_matcap(make_builtin_matcap("clay"));
  EXPECT_FALSE(renderer.draws_as_last(target, camera, o)) << "a MatCap";
  ASSERT_TRUE(draw_until_repeated(renderer, target, camera, o));
  renderer.set_mesh(cube);
  EXPECT_FALSE(renderer.draws_as_last(target, camera, o)) << "a mesh";
  ASSERT_TRUE(draw_until_repeated(renderer, target, camera, o));
  TriangleMesh triangle;
  triangle.positions = {cube.mean(0), cube.mean(1), cube.mean(2)};
  triangle.normals.assign(3, Vec3(0, 0, 1));
  triangle.triangles = {{0, 1, 2}};
  renderer.set_triangles(triangle);
  EXPECT_FALSE(renderer.draws_as_last(target, camera, o)) << "static triangles";
  ASSERT_TRUE(draw_until_repeated(renderer, target, camera, o));
  renderer.recompute_all();
  EXPECT_FALSE(renderer.draws_as_last(target, camera, o)) << "the compute passes";
  ASSERT_TRUE(draw_until_repeated(renderer, target, camera, o));
  renderer.surface_cache().set_hysteresis(1.25f);
  EXPECT_FALSE(renderer.draws_as_last(target, camera, o)) << "the surface cache's settings";
}

// Wherever the renderer says a frame repeats the last, drawing it again gives the same pixels in
// every attachment: after an edit, cached and live, welded at capture and when settled, with the grid.
TEST_F(RepeatedFrames, ARepeatedFrameIsWhatDrawingItAgainGives) {
  const CovarianceMesh torus = make_sample("torus");
  for (const SurfaceCache::Weld weld : {SurfaceCache::Weld::at_capture, SurfaceCache::Weld::when_settled}) {
    for (const bool wireframe : {false, true}) {
      for (const bool cached : {true, false}) {
        SCOPED_TRACE("weld " + std::to_string(int(weld)) + (wireframe ? ", wireframe" : "") +
                     (cached ? ", cached" : ", live"));
        SurfaceRenderer renderer;
        renderer.surface_cache().set_weld(weld);
        renderer.set_mesh(torus);
        RenderTarget target(kWidth, kHeight);
        const Camera camera = frame_mesh(torus);
        DrawOptions o;
        o.level = 12.0f;  // uniform: an edit evaluates welded vertices again where they are
        o.pixels = 0.0f;
        o.wireframe = wireframe;
        o.surface_cache = cached;
        ASSERT_TRUE(draw_until_repeated(renderer, target, camera, o));
        CovarianceMesh edited = torus;
        edited.covariances[4] *= 0.25;
        renderer.update_vertices(edited, {4});
        ASSERT_TRUE(draw_until_repeated(renderer, target, camera, o));
        const Image kept[3] = {target.read(0), target.read(1), target.read(2)};
        renderer.draw(target, camera, o);
        for (int a = 0; a < 3; ++a) EXPECT_EQ(target.read(a).pixels, kept[a].pixels) << "attachment " << a;
        EXPECT_TRUE(renderer.draws_as_last(target, camera, o));
      }
    }
  }
}

}  // namespace
}  // namespace gps
