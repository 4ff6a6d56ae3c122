// The GPU draws a mesh in a normalised frame (render/gl/normalised_frame.h): the torus scaled
// far down or up, or moved far from the origin, renders the image it renders at scale 1, and its
// position AOV is that render's mapped by the same affine map, within float precision.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/modelling/samples.h"
#include "render/gl/render_target.h"
#include "render/pipeline/surface_renderer.h"
#include "core/evaluation/tessellator.h"
#include "tests/support/gl_fixture.h"
#include "tests/support/plan_fixture.h"
#include "view/camera.h"

namespace gps {
namespace {

using FrameScale = test::GlTest;

constexpr int kSize = 192;

struct Render {
  Image color, position, normal;
};

// x' = scale · x + offset on every mean, Σ' = scale² Σ.
CovarianceMesh mapped(const CovarianceMesh& mesh, double scale, const Vec3& offset) {
  CovarianceMesh out = mesh;
  for (size_t i = 0; i < mesh.n_vertices(); ++i) {
    out.set_mean(i, scale * mesh.mean(i) + offset);
    out.set_covariance(i, scale * scale * mesh.covariance(i));
  }
  return out;
}

// static_triangles: the CPU evaluator's tessellation drawn as triangles (render --exact, --reference).
Render render(const CovarianceMesh& mesh, bool cached, bool overlays, bool static_triangles) {
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh);
  if (static_triangles) {
    const test::PlannedMesh cpu(mesh, PlanOptions{});
    renderer.set_triangles(tessellate(cpu.tables.plans, cpu.points, 12));
  }
  RenderTarget target(kSize, kSize);
  DrawOptions o;
  o.level = 12;
  o.pixels = 0;
  o.surface_cache = cached;
  o.mesh_lines = o.ellipsoids = overlays;
  o.static_triangles = static_triangles;
  const Camera camera = frame_mesh(mesh);
  renderer.draw(target, camera, o);
  if (cached) renderer.draw(target, camera, o);  // the second frame draws the stored triangles
  return {target.read(0), target.read(1), target.read(2)};
}

bool covered(const Image& position, int x, int y) { return position.at(x, y, 3) > 0.5f; }

void expect_same_image(double scale, const Vec3& offset, bool cached, bool overlays = false,
                       bool static_triangles = false) {
  const CovarianceMesh torus = make_sample("torus");
  const CovarianceMesh moved = mapped(torus, scale, offset);
  const Render a = render(torus, cached, overlays, static_triangles),
               b = render(moved, cached, overlays, static_triangles);
  const std::string what = "scale " + std::to_string(scale) + ", offset " + std::to_string(offset.x()) +
                           (cached ? ", cached" : "") + (overlays ? ", overlays" : "") +
                           (static_triangles ? ", static triangles" : "");
  const double diagonal = bounding_box_diagonal(torus) * scale;
  // A float AOV holds a world position to its own precision only.
  const double position_tolerance = 1e-4 * diagonal + 4e-7 * offset.cwiseAbs().maxCoeff();
  long long pixels = 0, covered_a = 0, color_off = 0, coverage_off = 0, position_off = 0, normal_off = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      ++pixels;
      const bool in_a = covered(a.position, x, y), in_b = covered(b.position, x, y);
      covered_a += in_a;
      for (int c = 0; c < 3; ++c) {
        const float ca = a.color.at(x, y, c), cb = b.color.at(x, y, c);
        if (!(std::abs(ca - cb) <= 2.0f / 255.0f)) {
          ++color_off;
          break;
        }
      }
      if (in_a != in_b) {
        ++coverage_off;
        continue;
      }
      if (!in_a) continue;
      const Vec3 pa(a.position.at(x, y, 0), a.position.at(x, y, 1), a.position.at(x, y, 2));
      const Vec3 pb(b.position.at(x, y, 0), b.position.at(x, y, 1), b.position.at(x, y, 2));
      if (!((pb - (scale * pa + offset)).norm() <= position_tolerance)) ++position_off;
      const Vec3 na(a.normal.at(x, y, 0), a.normal.at(x, y, 1), a.normal.at(x, y, 2));
      const Vec3 nb(b.normal.at(x, y, 0), b.normal.at(x, y, 1), b.normal.at(x, y, 2));
      if (!((na - nb).norm() <= 1e-3)) ++normal_off;
    }
  }
  ASSERT_GT(covered_a, pixels / 10) << what;
  // Only a silhouette pixel may flip where the frame's float rounding differs in the last bit.
  const long long allowed = std::max(2LL, covered_a / 500);
  EXPECT_LE(color_off, allowed) << what;
  if (overlays) return;  // the ellipsoids' lines leave the AOVs under them undefined
  EXPECT_LE(coverage_off, allowed) << what;
  EXPECT_LE(position_off, allowed) << what;
  EXPECT_LE(normal_off, allowed) << what;
}

TEST_F(FrameScale, TinyTorusRendersAsAtScaleOne) { expect_same_image(1e-6, Vec3::Zero(), false); }

TEST_F(FrameScale, HugeTorusRendersAsAtScaleOne) { expect_same_image(1e10, Vec3::Zero(), false); }

TEST_F(FrameScale, FarTorusRendersAsAtTheOrigin) { expect_same_image(1.0, Vec3(1e7, 1e7, 1e7), false); }

TEST_F(FrameScale, CachedFramesFollowTheFrame) {
  expect_same_image(1e10, Vec3::Zero(), true);
  expect_same_image(1.0, Vec3(1e7, 1e7, 1e7), true);
}

// The cage lines and the covariance ellipsoids are drawn in the frame too.
TEST_F(FrameScale, OverlaysFollowTheFrame) {
  expect_same_image(1.0, Vec3(1e7, 1e7, 1e7), false, true);
  expect_same_image(1e-6, Vec3::Zero(), false, true);
  expect_same_image(1e10, Vec3::Zero(), false, true);
}

// The CPU's triangles (--exact, --reference) are kept in the frame too.
TEST_F(FrameScale, StaticTrianglesFollowTheFrame) {
  expect_same_image(1.0, Vec3(1e7, 1e7, 1e7), false, false, true);
  expect_same_image(1e10, Vec3::Zero(), false, false, true);
}

TEST_F(FrameScale, StoredTrianglesAreInWorldCoordinates) {
  const CovarianceMesh torus = mapped(make_sample("torus"), 1e3, Vec3(5e3, 0, 0));
  SurfaceRenderer renderer;
  renderer.set_mesh(torus);
  RenderTarget target(64, 64);
  DrawOptions o;
  o.level = 4;
  o.pixels = 0;
  o.surface_cache = true;
  renderer.draw(target, frame_mesh(torus), o);
  renderer.draw(target, frame_mesh(torus), o);
  const TriangleMesh stored = renderer.surface_cache().stored_triangles();
  ASSERT_FALSE(stored.positions.empty());
  Vec3 lo, hi;
  bounding_box(torus, lo, hi);
  const Vec3 margin = Vec3::Constant(0.1 * (hi - lo).norm());
  for (const Vec3& p : stored.positions) {
    EXPECT_TRUE((p.array() >= (lo - margin).array()).all() && (p.array() <= (hi + margin).array()).all())
        << p.transpose();
  }
}

}  // namespace
}  // namespace gps
