// Hidden faces (DrawOptions::hidden_patches, hidden_edges): their patches and lines are not drawn,
// and everything else is drawn exactly as without them; nothing hidden is the plain frame.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "core/modelling/samples.h"
#include "core/plans/patch_faces.h"
#include "render/gl/render_target.h"
#include "render/pipeline/surface_renderer.h"
#include "tests/support/gl_fixture.h"

namespace gps {
namespace {

using HiddenPatches = test::GlTest;

constexpr int kSize = 128;

struct Frame {
  Image layers[3];  // colour, position, normal (w: coverage)
  bool covered(size_t pixel) const { return layers[2].pixels[4 * pixel + 3] != 0.0f; }
  bool same_pixel(const Frame& other, size_t pixel) const {
    for (int l = 0; l < 3; ++l) {
      const size_t c = size_t(layers[l].channels);
      if (std::memcmp(&layers[l].pixels[c * pixel], &other.layers[l].pixels[c * pixel], c * sizeof(float)) != 0)
        return false;
    }
    return true;
  }
};

Frame draw(SurfaceRenderer& renderer, const RenderTarget& target, const Camera& camera, const DrawOptions& o) {
  renderer.draw(target, camera, o);
  Frame f;
  for (int a = 0; a < 3; ++a) f.layers[a] = target.read(a);
  return f;
}

size_t differing_pixels(const Frame& a, const Frame& b) {
  size_t count = 0;
  for (size_t p = 0; p < size_t(kSize * kSize); ++p) count += !a.same_pixel(b, p);
  return count;
}

// The face of the cube whose centre lies nearest the camera: the one seen face on.
int front_face(const CovarianceMesh& cube, const Camera& camera) {
  const glm::dvec3 eye(camera.eye());
  int best = -1;
  double nearest = 1e300;
  for (int f = 0; f < int(cube.n_faces()); ++f) {
    Vec3 centre = Vec3::Zero();
    for (const int v : cube.face(size_t(f))) centre += 0.25 * cube.mean(size_t(v));
    const double d = (centre - Vec3(eye.x, eye.y, eye.z)).norm();
    if (d < nearest) nearest = d, best = f;
  }
  return best;
}

// Transform feedback of the tessellated vertices: a hidden octagon's and a quad's patches give none,
// and every other patch's vertices are bit for bit those of the full draw, in the same order.
TEST_F(HiddenPatches, HiddenPatchesAreNotTessellatedAndTheOthersAreUnchanged) {
  const CovarianceMesh cylinder = make_sample("cylinder");  // 16 quads and two octagons
  SurfaceRenderer renderer;
  renderer.set_mesh(cylinder);
  const PatchPlans& plans = renderer.tables().plans;
  int octagon = -1, quad = -1;
  for (int f = 0; f < int(cylinder.n_faces()); ++f) (cylinder.face_size(size_t(f)) == 8 ? octagon : quad) = f;
  const std::vector<int> hidden = patches_of_faces(cylinder.topology(), plans, {octagon, quad});
  ASSERT_EQ(hidden.size(), 9u);
  DrawOptions o;
  o.level = 4.0f;
  const Camera camera = frame_mesh(cylinder);
  const auto all = renderer.capture_vertices(camera, o, kSize, kSize);
  o.hidden_patches = &hidden;
  const auto shown = renderer.capture_vertices(camera, o, kSize, kSize);
  std::vector<TessellatedVertex> expected;
  for (const TessellatedVertex& t : all)
    if (!std::binary_search(hidden.begin(), hidden.end(), int(t.patch))) expected.push_back(t);
  ASSERT_LT(expected.size(), all.size());
  ASSERT_EQ(shown.size(), expected.size());
  EXPECT_EQ(std::memcmp(shown.data(), expected.data(), shown.size() * sizeof(TessellatedVertex)), 0);
  // Hiding every patch draws nothing.
  std::vector<int> every(size_t(plans.n_patches()));
  for (size_t p = 0; p < every.size(); ++p) every[p] = int(p);
  o.hidden_patches = &every;
  EXPECT_TRUE(renderer.capture_vertices(camera, o, kSize, kSize).empty());
}

// The cube seen face on, its front face hidden: where that face was not drawn the frame is the full
// frame's; where the rest was not drawn it is the front face's alone; behind the front face the
// inside of the cube shows. With the surface cache asked for, the frame is the live one; nothing
// hidden is the plain (cached) frame exactly.
TEST_F(HiddenPatches, AHiddenFaceShowsWhatIsBehindItAndNothingElseChanges) {
  const CovarianceMesh cube = make_sample("cube");
  SurfaceRenderer renderer;
  renderer.set_mesh(cube);
  const RenderTarget target(kSize, kSize);
  const Camera camera = frame_mesh(cube, 0.0f, 0.0f);
  const int front = front_face(cube, camera);
  const std::vector<int> hidden = patches_of_faces(cube.topology(), renderer.tables().plans, {front});
  std::vector<int> others;
  for (int p = 0; p < renderer.tables().plans.n_patches(); ++p)
    if (!std::binary_search(hidden.begin(), hidden.end(), p)) others.push_back(p);

  DrawOptions o;
  o.surface_cache = false;
  const Frame full = draw(renderer, target, camera, o);
  o.hidden_patches = &hidden;
  const Frame without = draw(renderer, target, camera, o);
  o.hidden_patches = &others;
  const Frame alone = draw(renderer, target, camera, o);

  size_t revealed = 0;
  for (size_t p = 0; p < size_t(kSize * kSize); ++p) {
    if (!alone.covered(p)) {
      EXPECT_TRUE(full.same_pixel(without, p)) << "pixel " << p;
    }
    if (!without.covered(p)) {
      EXPECT_TRUE(full.same_pixel(alone, p)) << "pixel " << p;
    }
    if (alone.covered(p) && without.covered(p) && !full.same_pixel(without, p)) ++revealed;
  }
  EXPECT_GT(revealed, size_t(kSize * kSize / 10)) << "the inside behind the front face";
  const size_t centre = size_t(kSize / 2) * kSize + kSize / 2;
  EXPECT_TRUE(without.covered(centre));  // the back face, seen from inside
  EXPECT_FALSE(full.same_pixel(without, centre));

  o.surface_cache = true;
  o.hidden_patches = &hidden;
  EXPECT_EQ(differing_pixels(draw(renderer, target, camera, o), without), 0u);
  o.hidden_patches = nullptr;
  const Frame cached = draw(renderer, target, camera, o);
  const std::vector<int> none;
  o.hidden_patches = &none;
  EXPECT_EQ(differing_pixels(draw(renderer, target, camera, o), cached), 0u);
}

// Mesh lines: every edge hidden is the frame without lines; none hidden, the frame with all of them.
TEST_F(HiddenPatches, HiddenEdgesAreLeftOutOfTheMeshLines) {
  const CovarianceMesh cube = make_sample("cube");
  SurfaceRenderer renderer;
  renderer.set_mesh(cube);
  const RenderTarget target(kSize, kSize);
  const Camera camera = frame_mesh(cube);
  DrawOptions o;
  const Frame plain = draw(renderer, target, camera, o);
  o.mesh_lines = true;
  const Frame lines = draw(renderer, target, camera, o);
  ASSERT_GT(differing_pixels(lines, plain), 0u);
  const std::vector<char> all(cube.n_edges(), 1), none(cube.n_edges(), 0);
  o.hidden_edges = &all;
  EXPECT_EQ(differing_pixels(draw(renderer, target, camera, o), plain), 0u);
  o.hidden_edges = &none;
  EXPECT_EQ(differing_pixels(draw(renderer, target, camera, o), lines), 0u);
  std::vector<char> one = none;
  one[0] = 1;
  o.hidden_edges = &one;
  const Frame one_hidden = draw(renderer, target, camera, o);
  EXPECT_GT(differing_pixels(one_hidden, lines), 0u);
  EXPECT_GT(differing_pixels(one_hidden, plain), 0u);
}

}  // namespace
}  // namespace gps
