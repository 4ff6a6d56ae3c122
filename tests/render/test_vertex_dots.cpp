// Vertex dots (render/overlays/vertex_dots.h): each listed vertex gets a dot of the style's colour
// centred on its pixel, nothing else changes, in the renderer's frame wherever it is (far from the
// origin, turned with a mesh moved whole); a moved vertex's dot moves; a vertex the mesh does not
// have is refused.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstdlib>

#include "core/modelling/samples.h"
#include "core/support/error.h"
#include "render/image/image_io.h"
#include "render/overlays/vertex_dots.h"
#include "render/pipeline/surface_renderer.h"
#include "tests/support/gl_fixture.h"
#include "tests/support/overlay_shots.h"
#include "view/camera.h"
#include "view/projection.h"

namespace gps {
namespace {

constexpr int kSize = 240;
constexpr float kDiameter = 7.0f;

using test::rgb_at;

struct Shot {
  Image plain, dotted;
  std::vector<glm::vec2> centres;  // the listed vertices' pixels, where in front of the eye
};

// The surface of `shown` under `camera`, then the dots of `dotted`'s `vertices` over it, in the
// renderer's frame after it showed `shown`.
Shot shoot(SurfaceRenderer& renderer, VertexDots& dots, const CovarianceMesh& dotted, const std::vector<int>& vertices,
           const Camera& camera, const std::string& name) {
  dots.set_vertices(dotted, vertices, renderer.frame());
  EXPECT_EQ(dots.count(), vertices.size());
  const test::OverlayShot shot = test::shoot_over(renderer, camera, kSize, [&](const RenderTarget& target) {
    dots.draw(target, camera, VertexDots::Style{glm::vec4(1.0f, 0.0f, 1.0f, 1.0f), kDiameter});
  });
  Shot s{shot.plain, shot.over, {}};
  for (const int v : vertices)
    if (const auto p = visible_pixel(camera, kSize, kSize, dotted.mean(size_t(v)))) s.centres.emplace_back(p->x, p->y);
  if (std::getenv("GPS_KEEP_IMAGES")) write_image("vertex_dots_" + name + ".png", s.dotted);
  return s;
}

// Every dot's centre pixel is the dot's colour, and every pixel that changed lies on a dot.
void expect_dots(const Shot& s, const std::string& name) {
  ASSERT_FALSE(s.centres.empty()) << name;
  int checked = 0;
  for (const glm::vec2& c : s.centres) {
    const int x = int(c.x), y = int(c.y);
    if (x < 4 || y < 4 || x >= kSize - 4 || y >= kSize - 4) continue;
    EXPECT_LT(glm::length(rgb_at(s.dotted, x, y) - glm::vec3(1.0f, 0.0f, 1.0f)), 0.02f)
        << name << ": dot at " << x << ", " << y;
    ++checked;
  }
  EXPECT_GT(checked, 0) << name;
  int changed = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      if (glm::length(rgb_at(s.dotted, x, y) - rgb_at(s.plain, x, y)) < 1e-3f) continue;
      ++changed;
      float nearest = 1e9f;
      for (const glm::vec2& c : s.centres) nearest = std::min(nearest, glm::length(glm::vec2(x + 0.5f, y + 0.5f) - c));
      EXPECT_LE(nearest, 0.5f * kDiameter + 1.0f) << name << ": pixel " << x << ", " << y << " off every dot";
    }
  EXPECT_GT(changed, 0) << name;
}

std::vector<int> every_seventh(const CovarianceMesh& mesh) {
  std::vector<int> out;
  for (size_t v = 0; v < mesh.n_vertices(); v += 7) out.push_back(int(v));
  return out;
}

// A world direction across the view: the view's x axis.
Vec3 across_view(const Camera& camera) {
  const glm::dmat4 view = camera.view_double();
  return Vec3(view[0][0], view[1][0], view[2][0]);
}

using VertexDotsTest = test::GlTest;

TEST_F(VertexDotsTest, ADotOnEachListedVertexAndNowhereElse) {
  for (const Vec3& shift : {Vec3(0.0, 0.0, 0.0), Vec3(3e5, -2e5, 1e5)}) {
    CovarianceMesh mesh = make_sample("pawn");
    for (size_t v = 0; v < mesh.n_vertices(); ++v) mesh.set_mean(v, mesh.mean(v) + shift);
    SurfaceRenderer renderer;
    renderer.set_mesh(mesh);
    const std::string name = shift.norm() > 0.0 ? "far" : "near";
    VertexDots dots;
    expect_dots(shoot(renderer, dots, mesh, every_seventh(mesh), frame_mesh(mesh, 20.0f, 15.0f), name), name);
  }
}

TEST_F(VertexDotsTest, InTheFrameOfAMeshMovedWholeAndAfterAVertexMoved) {
  const CovarianceMesh mesh = make_sample("pawn");
  CovarianceMesh moved = mesh;
  const Mat3 turn = Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
  for (size_t v = 0; v < mesh.n_vertices(); ++v) {
    moved.set_mean(v, 1.3 * turn * mesh.mean(v) + Vec3(0.4, -0.2, 0.1));
    moved.set_covariance(v, 1.69 * turn * mesh.covariance(v) * turn.transpose());
  }
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh);
  std::vector<int> all(mesh.n_vertices());
  for (size_t v = 0; v < all.size(); ++v) all[v] = int(v);
  renderer.update_vertices(moved, all);
  ASSERT_TRUE(renderer.frame().turned());
  const Camera camera = frame_mesh(moved, 20.0f, 15.0f);
  VertexDots dots;
  expect_dots(shoot(renderer, dots, moved, every_seventh(moved), camera, "turned"), "turned");

  CovarianceMesh edited = moved;
  edited.set_mean(14, edited.mean(14) + 0.3 * bounding_box_diagonal(moved) * across_view(camera));
  const Shot before = shoot(renderer, dots, moved, {14}, camera, "before");
  const Shot after = shoot(renderer, dots, edited, {14}, camera, "after");
  expect_dots(before, "one vertex");
  expect_dots(after, "the vertex moved");
  ASSERT_EQ(before.centres.size(), 1u);
  ASSERT_EQ(after.centres.size(), 1u);
  EXPECT_GT(glm::length(after.centres[0] - before.centres[0]), 2.0f * kDiameter);
}

TEST_F(VertexDotsTest, NoneListedDrawsNothingAndAVertexOutsideIsRefused) {
  const CovarianceMesh mesh = make_sample("pawn");
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh);
  VertexDots dots;
  const Shot none = shoot(renderer, dots, mesh, {}, frame_mesh(mesh), "none");
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) ASSERT_EQ(rgb_at(none.dotted, x, y), rgb_at(none.plain, x, y));
  EXPECT_THROW(dots.set_vertices(mesh, {int(mesh.n_vertices())}, renderer.frame()), Error);
  EXPECT_THROW(dots.set_vertices(mesh, {-1}, renderer.frame()), Error);
  EXPECT_EQ(dots.count(), 0u) << "the dots held before a refusal stay";
}

}  // namespace
}  // namespace gps
