// The thesis' comparison images (Figs. 4.4, 4.8): the GPU's position and normal AOVs against the
// CPU reference's, ×200 and ×5000, as `gpsurf diff` writes them, are black. The reference is GPS
// subdivision with limit projection and its exact limit normals, at the level whose vertices are the
// tessellation's, drawn in the GPU's own triangles, corner for corner
// (render/comparison/reference_triangles.h): every pixel then compares one surface at one parameter,
// evaluated twice and rasterised alike. Under Loop, GL's triangle tessellation puts its inner rings
// off the dyadic grid, so no reference level has its vertices: there the reference is the exact
// evaluator (equal to subdivision and limit projection at every parameter: tests/core) at the
// parameters of the GPU's own vertices.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include <glm/glm.hpp>

#include "core/support/error.h"
#include "core/modelling/samples.h"
#include "render/image/difference_image.h"
#include "render/comparison/exact_triangles.h"
#include "render/image/image_io.h"
#include "render/comparison/reference_triangles.h"
#include "render/gl/render_target.h"
#include "render/pipeline/surface_renderer.h"
#include "tests/support/gl_fixture.h"
#include "view/camera.h"

namespace gps {
namespace {

using ComparisonImages = test::GlTest;

constexpr int kSize = 256;
constexpr int kLevel = 16;  // tessellation level: 16 segments per patch edge

struct Aovs {
  Image position, normal;
};

DrawOptions options_at_level(bool static_triangles) {
  DrawOptions o;
  o.level = float(kLevel);
  o.pixels = 0;
  o.static_triangles = static_triangles;
  return o;
}

Aovs draw(SurfaceRenderer& renderer, const Camera& camera, bool reference) {
  RenderTarget target(kSize, kSize);
  renderer.draw(target, camera, options_at_level(reference));
  return {target.read(1), target.read(2)};
}

// What a difference image shows: the share of covered pixels with any channel at 1/255 or more,
// and the brightest channel, in the 8-bit image `gpsurf diff` writes.
struct Shown {
  double lit = 0, visible = 0;  // any channel at 1/255, at 8/255 or more
  int brightest = 0;
  DifferenceStats stats;
  // Where the pixels at 8/255 are, to tell a GPU's error from the image's sensitivity: by the plan
  // node the GPU evaluated there (regular, terminal, extraordinary), and those where the surface is
  // seen within 15° of edge-on.
  int visible_by_kind[3] = {0, 0, 0};
  int visible_edge_on = 0;
};

Shown shown(const Aovs& gpu, const Aovs& reference, AovKind kind, const Camera& camera) {
  Shown s;
  const Image d = kind == AovKind::position
                      ? difference_image(gpu.position, reference.position, kind, 200.0, 0.0, s.stats)
                      : difference_image(gpu.normal, reference.normal, kind, 5000.0, 0.0, s.stats);
  int lit = 0, visible = 0;
  for (size_t i = 0; i < d.pixels.size(); i += 3) {
    int brightest = 0;
    for (int c = 0; c < 3; ++c) brightest = std::max(brightest, int(std::lround(d.pixels[i + size_t(c)] * 255.0f)));
    lit += brightest > 0;
    visible += brightest >= 8;
    if (brightest >= 8) {
      const size_t n = gpu.normal.channels * (i / 3), p = gpu.position.channels * (i / 3);
      const int node_kind =
          int(gpu.normal.pixels[n + 3]) - 2;  // shade_frag.glsl: 2 regular, 3 terminal, 4 extraordinary
      if (node_kind >= 0 && node_kind < 3) ++s.visible_by_kind[node_kind];
      const glm::vec3 normal(gpu.normal.pixels[n], gpu.normal.pixels[n + 1], gpu.normal.pixels[n + 2]);
      const glm::vec3 position(gpu.position.pixels[p], gpu.position.pixels[p + 1], gpu.position.pixels[p + 2]);
      s.visible_edge_on +=
          std::abs(glm::dot(normal, glm::normalize(camera.eye() - position))) < std::sin(glm::radians(15.0f));
    }
    s.brightest = std::max(s.brightest, brightest);
  }
  s.lit = s.stats.covered ? double(lit) / s.stats.covered : 1.0;
  s.visible = s.stats.covered ? double(visible) / s.stats.covered : 1.0;
  return s;
}

// Expects both images black (as below), the normal image with at most `normal_share` of the covered
// pixels at 8/255; prints what they show.
void expect_black(const char* name, const Aovs& gpu, const Aovs& reference, const Camera& camera, double normal_share) {
  for (const AovKind kind : {AovKind::position, AovKind::normal}) {
    const Shown s = shown(gpu, reference, kind, camera);
    const char* what = kind == AovKind::position ? "position x200" : "normal x5000";
    std::printf(
        "%-14s %-14s %6d pixels, %6.3f%% lit, %6.3f%% at 8/255, brightest %3d/255, largest difference %.1e, mean "
        "%.1e\n",
        name, what, s.stats.covered, 100.0 * s.lit, 100.0 * s.visible, s.brightest, s.stats.max, s.stats.mean);
    if (s.visible > 0)
      std::printf(
          "%-14s %-14s at 8/255: %d regular, %d terminal, %d extraordinary node pixels; %d seen within 15 deg of "
          "edge-on\n",
          name, what, s.visible_by_kind[0], s.visible_by_kind[1], s.visible_by_kind[2], s.visible_edge_on);
    EXPECT_GT(s.stats.covered, kSize * kSize / 20) << name;
    EXPECT_LE(s.stats.coverage_mismatch, s.stats.covered / 10000) << name << " " << what;
    EXPECT_LE(s.visible, kind == AovKind::normal ? normal_share : 0.01) << name << " " << what;
  }
}

// Black: at most 1 % of the covered pixels at 8/255 or more in any channel (a position 1.6e-4 of the
// diagonal apart, a normal component 6e-6), and no pixel covered in one image only but where a
// silhouette edge passes within float rounding of a pixel centre (at most 1 in 10,000 covered). The
// share of pixels lit at all (1/255) and the brightest are reported. cone-concave's apex covariance
// is 1e-5 (q̂ ~ 1e5 I) where its surface folds inwards: up to 4 % of its normal pixels may reach
// 8/255, this image's sensitivity there more than the GPU's error (normals turned by as little as
// 1e-6 light a few percent of its pixels). cone-pointy, with the same apex, stays within 1 % because
// the GPU sums q̄ about nearby anchors (shaders/plan_point.glsl) and boundary leaves take their
// phantom points into the basis (core/patches/patch_basis.h), so that no net point is a large
// difference in float.
TEST_F(ComparisonImages, AreBlackOnTheValenceSamplesTheWirecubeAndTheCones) {
  const PlanOptions options{Scheme::catmull_clark};
  for (const char* name : {"valence3", "valence5", "valence8", "valence10", "wirecube", "cone", "cone-pointy",
                           "cone-concave", "cone-plateau", "cone-cylinder"}) {
    const CovarianceMesh mesh = make_sample(name);
    // Level 16 is 16 segments along every mesh edge, a triangle's three half-size patches (a
    // Catmull-Clark step's quads) included: the reference's level 4 has the same vertices.
    const int levels = int(std::log2(kLevel));
    SurfaceRenderer renderer;
    renderer.set_mesh(mesh, options);
    const Camera camera = frame_mesh(mesh);
    const Aovs gpu = draw(renderer, camera, false);
    renderer.set_triangles(
        reference_in_patch_triangles(renderer, mesh, camera, options_at_level(false), kSize, kSize, levels));
    const Aovs reference = draw(renderer, camera, true);
    const bool folded_needle = std::string(name) == "cone-concave";
    expect_black(name, gpu, reference, camera, folded_needle ? 0.04 : 0.01);
  }
}

// The reference in the patches' triangles is the reference at their vertices: equal to the exact
// evaluator's values in the same triangles (tests/core: the two surfaces are one), a triangle's
// half-size patches included (cone); off the reference's grid it refuses.
TEST_F(ComparisonImages, ReferenceInThePatchesTrianglesHasTheirVertices) {
  const PlanOptions options{Scheme::catmull_clark};
  for (const char* name : {"valence5", "cone"}) {
    const CovarianceMesh mesh = make_sample(name);
    SurfaceRenderer renderer;
    renderer.set_mesh(mesh, options);
    const Camera camera = frame_mesh(mesh);
    const TriangleMesh exact = exact_triangles(renderer, mesh, camera, options_at_level(false), kSize, kSize).triangles;
    const TriangleMesh reference =
        reference_in_patch_triangles(renderer, mesh, camera, options_at_level(false), kSize, kSize, 4).triangles;
    ASSERT_EQ(reference.triangles, exact.triangles) << name;
    ASSERT_EQ(reference.positions.size(), exact.positions.size()) << name;
    double position = 0, normal = 0;
    for (size_t i = 0; i < exact.positions.size(); ++i) {
      position = std::max(position, (reference.positions[i] - exact.positions[i]).norm());
      normal = std::max(normal, (reference.normals[i] - exact.normals[i]).norm());
    }
    EXPECT_LT(position, 1e-12) << name;
    EXPECT_LT(normal, 1e-9) << name;
    DrawOptions off_grid = options_at_level(false);
    off_grid.level = 12.0f;
    EXPECT_THROW(reference_in_patch_triangles(renderer, mesh, camera, off_grid, kSize, kSize, 4), Error) << name;
  }
}

// The triangle samples under their own scheme, Loop, with the bounds above: black but cone-concave,
// held to Catmull-Clark's 4 %. The two cones with a needle apex (covariance 1e-5, q̂ ~ 1e5 I) stay
// within these bounds because each leaf's sums are taken about its heaviest point's anchor
// (shaders/plan_eval.glsl) and an extraordinary node's tangents are solved in double and made
// orthogonal before their cross product (nearly parallel there, they would lose the normal's digits).
TEST_F(ComparisonImages, AreBlackOnTheConesUnderLoop) {
  const PlanOptions options{Scheme::loop};
  for (const char* name : {"cone", "cone-pointy", "cone-concave", "cone-plateau", "cone-cylinder", "icosphere"}) {
    const CovarianceMesh mesh = make_sample(name);
    SurfaceRenderer renderer;
    renderer.set_mesh(mesh, options);
    const Camera camera = frame_mesh(mesh);
    const Aovs gpu = draw(renderer, camera, false);
    renderer.set_triangles(exact_triangles(renderer, mesh, camera, options_at_level(false), kSize, kSize));
    const Aovs reference = draw(renderer, camera, true);
    expect_black(name, gpu, reference, camera, std::string(name) == "cone-concave" ? 0.04 : 0.01);
  }
}

}  // namespace
}  // namespace gps
