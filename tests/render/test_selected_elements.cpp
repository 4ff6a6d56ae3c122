// Selected faces and edges highlighted (render/overlays/selected_elements.h): a face that looks at the
// eye is filled and outlined, one that looks away is not; an edge shows where one of its faces looks
// at the eye, a boundary edge always; in a perspective and a parallel view, far from the origin too.
#include <gtest/gtest.h>

#include <cstdlib>

#include "core/modelling/samples.h"
#include "core/support/error.h"
#include "render/image/image_io.h"
#include "render/overlays/selected_elements.h"
#include "render/pipeline/surface_renderer.h"
#include "tests/support/gl_fixture.h"
#include "tests/support/overlay_shots.h"
#include "view/camera.h"
#include "view/projection.h"

namespace gps {
namespace {

constexpr int kSize = 240;

using test::rgb_at;

// `mesh`'s surface under `camera`, then the highlight of `edges` and `faces` over it.
test::OverlayShot shoot(const CovarianceMesh& mesh, const std::vector<std::array<int, 2>>& edges,
                        const std::vector<int>& faces, const Camera& camera, const std::string& name) {
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh);
  SelectedElements highlight;
  highlight.set_elements(mesh, edges, faces, renderer.frame());
  const test::OverlayShot s = test::shoot_over(renderer, camera, kSize, [&](const RenderTarget& target) {
    highlight.draw(target, camera, SelectedElements::Style{});
  });
  if (std::getenv("GPS_KEEP_IMAGES")) write_image("selected_" + name + ".png", s.over);
  return s;
}

glm::dvec3 world(const Vec3& p) { return {p.x(), p.y(), p.z()}; }

// Whether face f of `mesh` looks at the eye of `camera` (its Newell normal towards the eye).
bool faces_eye(const CovarianceMesh& mesh, int f, const Camera& camera) {
  const std::span<const int> c = mesh.face(size_t(f));
  glm::dvec3 normal(0.0), centroid(0.0);
  for (size_t k = 0; k < c.size(); ++k) {
    normal += glm::cross(world(mesh.mean(size_t(c[k]))), world(mesh.mean(size_t(c[(k + 1) % c.size()]))));
    centroid += world(mesh.mean(size_t(c[k])));
  }
  centroid /= double(c.size());
  const glm::dvec3 towards = camera.orthographic ? camera.eye_offset() : camera.eye_double() - centroid;
  return glm::dot(normal, towards) > 0.0;
}

glm::vec2 pixel(const Camera& camera, const Vec3& p) {
  const auto q = project_to_pixel(camera, kSize, kSize, p);
  EXPECT_TRUE(q.has_value());
  return q ? glm::vec2(q->x, q->y) : glm::vec2(0.0f);
}

Vec3 centroid(const CovarianceMesh& mesh, int f) {
  Vec3 sum = Vec3::Zero();
  for (const int v : mesh.face(size_t(f))) sum += mesh.mean(size_t(v));
  return sum / double(mesh.face_size(size_t(f)));
}

bool same_image(const Image& a, const Image& b) {
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      if (glm::length(rgb_at(a, glm::vec2(x, y)) - rgb_at(b, glm::vec2(x, y))) > 1e-4f) return false;
  return true;
}

const glm::vec3 kEdge(1.0f, 170.0f / 255.0f, 40.0f / 255.0f), kOutline(1.0f, 190.0f / 255.0f, 80.0f / 255.0f),
    kFill(1.0f, 150.0f / 255.0f, 40.0f / 255.0f);
constexpr float kFillAlpha = 70.0f / 255.0f;

using SelectedElementsTest = test::GlTest;

// The cube from in front and from a parallel view, near the origin and far from it: each face
// selected alone shows filled and outlined where it looks at the eye, and changes nothing where not.
TEST_F(SelectedElementsTest, AFaceShowsWhereItLooksAtTheEye) {
  for (const bool parallel : {false, true})
    for (const Vec3& shift : {Vec3(0.0, 0.0, 0.0), Vec3(3e5, -2e5, 1e5)}) {
      CovarianceMesh cube = make_sample("cube");
      for (size_t v = 0; v < cube.n_vertices(); ++v) cube.set_mean(v, cube.mean(v) + shift);
      Camera camera = frame_mesh(cube, 30.0f, 20.0f);
      camera.orthographic = parallel;
      int shown = 0;
      for (int f = 0; f < int(cube.n_faces()); ++f) {
        const std::string name = std::string(parallel ? "parallel" : "perspective") + (shift.norm() > 0 ? " far" : "") +
                                 ", face " + std::to_string(f);
        const test::OverlayShot s = shoot(cube, {}, {f}, camera, "face");
        if (!faces_eye(cube, f, camera)) {
          EXPECT_TRUE(same_image(s.plain, s.over)) << name << " looks away but was drawn";
          continue;
        }
        ++shown;
        const glm::vec2 c = pixel(camera, centroid(cube, f));
        const glm::vec3 blended = glm::mix(rgb_at(s.plain, c), kFill, kFillAlpha);
        EXPECT_LT(glm::length(rgb_at(s.over, c) - blended), 0.02f) << name << ": the fill at its centre";
        const std::span<const int> corners = cube.face(size_t(f));
        const Vec3 middle = 0.5 * (cube.mean(size_t(corners[0])) + cube.mean(size_t(corners[1])));
        EXPECT_LT(glm::length(rgb_at(s.over, pixel(camera, middle)) - kOutline), 0.02f) << name << ": its outline";
      }
      EXPECT_EQ(shown, 3) << "the cube shows three faces from a corner";
    }
}

// An edge of a face that looks at the eye shows in the edge colour; one between two faces that look
// away does not; a boundary edge shows even where its one face looks away.
TEST_F(SelectedElementsTest, AnEdgeShowsWhereOneOfItsFacesLooksAtTheEyeOrOnTheBoundary) {
  const CovarianceMesh cube = make_sample("cube");
  const Camera camera = frame_mesh(cube, 30.0f, 20.0f);
  int front = 0, back = 0;
  for (size_t e = 0; e < cube.n_edges(); ++e) {
    const std::array<int, 2> ends = cube.edge(e);
    const int f0 = cube.connectivity().edge_faces[2 * e], f1 = cube.connectivity().edge_faces[2 * e + 1];
    const test::OverlayShot s = shoot(cube, {ends}, {}, camera, "edge");
    const std::string name = "edge " + std::to_string(ends[0]) + "-" + std::to_string(ends[1]);
    if (faces_eye(cube, f0, camera) || faces_eye(cube, f1, camera)) {
      ++front;
      const Vec3 middle = 0.5 * (cube.mean(size_t(ends[0])) + cube.mean(size_t(ends[1])));
      EXPECT_LT(glm::length(rgb_at(s.over, pixel(camera, middle)) - kEdge), 0.02f) << name;
    } else {
      ++back;
      EXPECT_TRUE(same_image(s.plain, s.over)) << name << " lies between faces that look away but was drawn";
    }
  }
  EXPECT_EQ(front, 9);
  EXPECT_EQ(back, 3);

  // One face of the cube, seen from behind: its boundary edges show, its fill does not.
  const CovarianceMesh square = make_covariance_mesh(
      {cube.mean(0), cube.mean(1), cube.mean(2), cube.mean(3)},
      {cube.covariance(0), cube.covariance(1), cube.covariance(2), cube.covariance(3)}, {{0, 1, 2, 3}});
  for (const float yaw : {30.0f, 210.0f}) {
    const Camera view = frame_mesh(square, yaw, 20.0f);
    if (faces_eye(square, 0, view)) continue;
    const Vec3 middle = 0.5 * (square.mean(0) + square.mean(1));
    const test::OverlayShot edge = shoot(square, {{0, 1}}, {}, view, "boundary");
    EXPECT_LT(glm::length(rgb_at(edge.over, pixel(view, middle)) - kEdge), 0.02f) << "a boundary edge seen from behind";
    const test::OverlayShot face = shoot(square, {}, {0}, view, "square");
    EXPECT_TRUE(same_image(face.plain, face.over)) << "a face seen from behind";
    return;
  }
  FAIL() << "neither view sees the square from behind";
}

TEST_F(SelectedElementsTest, ElementsOutsideTheMeshAreRefused) {
  const CovarianceMesh cube = make_sample("cube");
  SelectedElements highlight;
  EXPECT_THROW(highlight.set_elements(cube, {}, {6}, NormalisedFrame::of(cube)), Error);
  EXPECT_THROW(highlight.set_elements(cube, {{0, 8}}, {}, NormalisedFrame::of(cube)), Error);
  highlight.set_elements(cube, {{0, 5}}, {}, NormalisedFrame::of(cube));  // 0-5 is no edge of the cube: left out
  EXPECT_EQ(highlight.lines(), 0u);
}

}  // namespace
}  // namespace gps
