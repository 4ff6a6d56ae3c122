// A mesh moved whole by a rotation, a positive uniform scale and a translation is shown by moving the
// renderer's frame (render/gl/moved_frame.h): nothing is evaluated again, and the surface drawn is a rebuild's
// to within float rounding, before and after the edits and operations that follow it. Any other edit
// of every vertex is evaluated as before.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <tuple>
#include <string>

#include "core/modelling/affine_transform.h"
#include "core/modelling/extrude.h"
#include "core/modelling/samples.h"
#include "core/plans/surface_replanner.h"
#include "render/gl/moved_frame.h"
#include "render/gl/render_target.h"
#include "render/pipeline/surface_renderer.h"
#include "tests/support/gl_fixture.h"
#include "view/camera.h"

namespace gps {
namespace {

using MovedFrameTest = test::GlTest;

constexpr int kSize = 160;

CovarianceMesh moved_by(const CovarianceMesh& mesh, const AffineMap& map) {
  return transform_vertices(mesh, {}, map).mesh;
}

const AffineMap kScaleAndMove = [] {
  AffineMap m = AffineMap::about(Vec3(0.3, -0.2, 0.1), 1.7 * Mat3::Identity());
  m.translation += Vec3(2.5, -1.0, 0.75);
  return m;
}();

const AffineMap kTurnScaleAndMove = [] {
  const Mat3 turn = Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
  AffineMap m = AffineMap::about(Vec3(0.3, -0.2, 0.1), 0.6 * turn);
  m.translation += Vec3(-1.5, 0.25, 3.0);
  return m;
}();

std::vector<int> every_vertex(const CovarianceMesh& mesh) {
  std::vector<int> all(mesh.n_vertices());
  for (size_t v = 0; v < all.size(); ++v) all[v] = int(v);
  return all;
}

TEST(MovedFrame, FindsTheRotationScaleAndTranslationOfEveryGaussian) {
  const CovarianceMesh mesh = make_sample("pawn");
  const NormalisedFrame frame = NormalisedFrame::of(mesh);
  const FramedGaussians framed = frame.gaussians_in_frame(mesh);
  for (const auto& [what, map, scale] : {std::tuple{"scaled and moved", kScaleAndMove, 1.7},
                                         std::tuple{"turned, scaled and moved", kTurnScaleAndMove, 0.6}}) {
    const CovarianceMesh moved = moved_by(mesh, map);
    FramedGaussians again;
    const std::optional<NormalisedFrame> to = moved_frame(frame, framed, moved, again);
    ASSERT_TRUE(to) << what;
    EXPECT_NEAR(to->unit, scale * frame.unit, 1e-12 * frame.unit) << what;
    EXPECT_LE((to->rotation_matrix() - map.linear / scale).norm(), 1e-12) << what;
    EXPECT_EQ(to->turned(), map.linear != scale * Mat3::Identity()) << what;
    const Vec3 centre = map.apply(Vec3(frame.centre.x, frame.centre.y, frame.centre.z));
    EXPECT_NEAR(glm::distance(to->centre, glm::dvec3(centre.x(), centre.y(), centre.z())), 0.0, 1e-12 * to->unit)
        << what;
    ASSERT_EQ(again.n_vertices(), mesh.n_vertices());
    for (size_t v = 0; v < mesh.n_vertices(); ++v) {
      EXPECT_LE((again.means[v] - framed.means[v]).norm(), 1e-13) << what << ", " << v;
      EXPECT_LE((again.covariances[v] - framed.covariances[v]).norm(), 1e-13 * framed.covariances[v].norm())
          << what << ", " << v;
    }
  }
}

TEST(MovedFrame, RefusesEveryOtherEdit) {
  const CovarianceMesh mesh = make_sample("pawn");
  const NormalisedFrame frame = NormalisedFrame::of(mesh);
  const FramedGaussians framed = frame.gaussians_in_frame(mesh);
  const double diagonal = bounding_box_diagonal(mesh);
  const Vec3 pivot(0.1, 0.2, 0.3);
  const Mat3 shear = (Mat3() << 1, 0.2, 0, 0, 1, 0, 0, 0, 1).finished();
  CovarianceMesh positions_only = mesh, one_mean = moved_by(mesh, kScaleAndMove),
                 one_covariance = moved_by(mesh, kScaleAndMove), fewer = mesh;
  for (size_t v = 0; v < mesh.n_vertices(); ++v) positions_only.set_mean(v, kScaleAndMove.apply(mesh.mean(v)));
  one_mean.set_mean(7, one_mean.mean(7) + Vec3(1e-9 * diagonal, 0, 0));
  one_covariance.set_covariance(7, one_covariance.covariance(7) * (1.0 + 1e-9));
  fewer = extrude_faces(mesh, {0}, 0.1).mesh;
  const std::vector<std::pair<std::string, CovarianceMesh>> edits = {
      {"unchanged", mesh},
      {"sheared", moved_by(mesh, AffineMap::about(pivot, shear))},
      {"scaled along x", moved_by(mesh, AffineMap::about(pivot, Vec3(2.0, 1.0, 1.0).asDiagonal()))},
      {"mirrored", moved_by(mesh, AffineMap::about(pivot, -Mat3::Identity()))},
      {"means alone scaled", positions_only},
      {"one mean off by a billionth", one_mean},
      {"one covariance off by a billionth", one_covariance},
      {"another vertex count", fewer}};
  for (const auto& [what, edited] : edits) {
    FramedGaussians again;
    EXPECT_FALSE(moved_frame(frame, framed, edited, again)) << what;
  }
}

// A turned frame is followed along its own axes: a cube stood on a corner has a world box half again
// as wide, but in the frame that turned with it, the box it had.
TEST(MovedFrame, ATurnedFrameFollowsTheMeshAlongItsOwnAxes) {
  const CovarianceMesh cube = make_sample("cube");
  const NormalisedFrame frame = NormalisedFrame::of(cube);
  const Mat3 stand = Eigen::Quaterniond::FromTwoVectors(Vec3(1, 1, 1), Vec3::UnitZ()).toRotationMatrix();
  const CovarianceMesh stood = moved_by(cube, AffineMap::about(Vec3::Zero(), stand));
  FramedGaussians again;
  const std::optional<NormalisedFrame> turned = moved_frame(frame, frame.gaussians_in_frame(cube), stood, again);
  ASSERT_TRUE(turned && turned->turned());
  EXPECT_GT(bounding_box_diagonal(stood), 1.25 * bounding_box_diagonal(cube));
  EXPECT_EQ(turned->following(stood), *turned);
  // Grown past the factor along its axes, it takes the mesh's own frame.
  const CovarianceMesh grown = moved_by(stood, AffineMap::about(Vec3::Zero(), 1.3 * Mat3::Identity()));
  EXPECT_EQ(turned->following(grown), NormalisedFrame::of(grown));
}

struct Drawn {
  Image color, position, normal;
};

Drawn draw(SurfaceRenderer& renderer, const Camera& camera) {
  RenderTarget target(kSize, kSize);
  DrawOptions o;
  o.level = 6;
  o.pixels = 0;
  renderer.draw(target, camera, o);
  return {target.read(0), target.read(1), target.read(2)};
}

// Two draws of the same surface: the colours, coverage, world positions and normals agree but for
// a few silhouette pixels where float rounding differs.
void expect_same_surface(const Drawn& a, const Drawn& b, double diagonal, const std::string& what) {
  long long covered = 0, off = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const bool in_a = a.position.at(x, y, 3) > 0.5f, in_b = b.position.at(x, y, 3) > 0.5f;
      covered += in_a;
      bool same = in_a == in_b;
      for (int c = 0; c < 3 && same; ++c) same = std::abs(a.color.at(x, y, c) - b.color.at(x, y, c)) <= 2.0f / 255.0f;
      for (int c = 0; c < 3 && same && in_a; ++c) {
        same = std::abs(a.position.at(x, y, c) - b.position.at(x, y, c)) <= 1e-4 * diagonal &&
               std::abs(a.normal.at(x, y, c) - b.normal.at(x, y, c)) <= 1e-3;
      }
      off += !same;
    }
  ASSERT_GT(covered, kSize * kSize / 10) << what;
  EXPECT_LE(off, std::max(2LL, covered / 500)) << what;
}

// The corner pass's limit points in world coordinates against a rebuild's.
void expect_same_corners(const SurfaceRenderer& shown, const SurfaceRenderer& rebuilt, const std::string& what) {
  const std::vector<glm::dvec3> a = shown.corner_limit_points(), b = rebuilt.corner_limit_points();
  ASSERT_EQ(a.size(), b.size()) << what;
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
    worst = std::max(worst, glm::distance(shown.frame().to_world(a[i]), rebuilt.frame().to_world(b[i])));
  EXPECT_LE(worst, 1e-5 * rebuilt.frame().unit) << what;
}

// The tessellated vertices read back (world positions and normals), and the surface cache's stored
// triangles, against a rebuild's.
void expect_same_read_back(SurfaceRenderer& shown, SurfaceRenderer& rebuilt, const Camera& camera, double diagonal,
                           const std::string& what) {
  DrawOptions o;
  o.level = 3;
  o.pixels = 0;
  const std::vector<TessellatedVertex> a = shown.capture_vertices(camera, o, kSize, kSize),
                                       b = rebuilt.capture_vertices(camera, o, kSize, kSize);
  ASSERT_EQ(a.size(), b.size()) << what;
  double position = 0.0, normal = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      position = std::max(position, double(std::abs(a[i].position[k] - b[i].position[k])));
      normal = std::max(normal, double(std::abs(a[i].normal[k] - b[i].normal[k])));
    }
  EXPECT_LE(position, 1e-5 * diagonal) << what << ": captured positions";
  EXPECT_LE(normal, 1e-4) << what << ": captured normals";
  const TriangleMesh stored = shown.surface_cache().stored_triangles(),
                     again = rebuilt.surface_cache().stored_triangles();
  ASSERT_EQ(stored.triangles.size(), again.triangles.size()) << what;
  ASSERT_GT(stored.triangles.size(), 0u) << what;
  position = normal = 0.0;
  for (size_t t = 0; t < stored.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int i = stored.triangles[t][k], j = again.triangles[t][k];
      position = std::max(position, (stored.positions[size_t(i)] - again.positions[size_t(j)]).norm());
      normal =
          std::max(normal, (stored.normals[size_t(i)].normalized() - again.normals[size_t(j)].normalized()).norm());
    }
  EXPECT_LE(position, 1e-5 * diagonal) << what << ": stored positions";
  EXPECT_LE(normal, 1e-4) << what << ": stored normals";
}

// Catmull-Clark with extraordinary vertices and Loop: moved whole by an edit of every vertex, the
// surface's frame moves, nothing is evaluated again (the next frame draws the stored triangles, with
// no capture), and it draws as the moved mesh set anew; so does a one-vertex edit after it.
TEST_F(MovedFrameTest, AnEditOfEveryVertexByOneRotationScaleAndTranslationMovesTheFrame) {
  for (const auto& [sample, map, scale] :
       {std::tuple{"pawn", kScaleAndMove, 1.7}, std::tuple{"pawn", kTurnScaleAndMove, 0.6},
        std::tuple{"icosphere", kScaleAndMove, 1.7}, std::tuple{"icosphere", kTurnScaleAndMove, 0.6}}) {
    const std::string name = std::string(sample) + (map.linear == scale * Mat3::Identity() ? ", scaled" : ", turned");
    const CovarianceMesh mesh = make_sample(sample);
    const CovarianceMesh moved = moved_by(mesh, map);
    const Camera camera = frame_mesh(moved);
    SurfaceRenderer renderer;
    renderer.set_mesh(mesh);
    draw(renderer, camera);
    draw(renderer, camera);
    const NormalisedFrame before = renderer.frame();
    const int captures = renderer.surface_cache().captures(), refreshes = renderer.surface_cache().refreshes();
    ASSERT_GT(captures, 0) << name;
    renderer.update_vertices(moved, every_vertex(moved));
    EXPECT_NE(renderer.frame(), before) << name;
    EXPECT_NEAR(renderer.frame().unit, scale * before.unit, 1e-12 * before.unit) << name;
    const Drawn shown = draw(renderer, camera);
    EXPECT_EQ(renderer.surface_cache().captures(), captures) << name;
    EXPECT_EQ(renderer.surface_cache().refreshes(), refreshes) << name;
    SurfaceRenderer rebuilt;
    rebuilt.set_mesh(moved);
    expect_same_surface(shown, draw(rebuilt, camera), bounding_box_diagonal(moved), name + ", moved");
    expect_same_corners(renderer, rebuilt, name + ", moved");
    expect_same_read_back(renderer, rebuilt, camera, bounding_box_diagonal(moved), name + ", moved");

    CovarianceMesh edited = moved;
    edited.set_mean(3, edited.mean(3) + 0.05 * bounding_box_diagonal(moved) * Vec3(0.3, 0.9, 0.2));
    renderer.update_vertices(edited, {3});
    rebuilt.set_mesh(edited);
    expect_same_surface(draw(renderer, camera), draw(rebuilt, camera), bounding_box_diagonal(edited),
                        name + ", then one vertex edited");
    expect_same_corners(renderer, rebuilt, name + ", then one vertex edited");
  }
}

// A stretch of every vertex, or a scale of their means alone, is evaluated again in the same frame.
TEST_F(MovedFrameTest, OtherEditsOfEveryVertexKeepTheFrame) {
  const CovarianceMesh mesh = make_sample("pawn");
  CovarianceMesh positions_only = mesh;
  for (size_t v = 0; v < mesh.n_vertices(); ++v) positions_only.set_mean(v, kScaleAndMove.apply(mesh.mean(v)));
  for (const auto& [what, edited] :
       {std::pair<std::string, CovarianceMesh>{
            "stretched", moved_by(mesh, AffineMap::about(Vec3::Zero(), Vec3(1.3, 1.0, 1.0).asDiagonal()))},
        {"means alone scaled", positions_only}}) {
    SurfaceRenderer renderer;
    renderer.set_mesh(mesh);
    const Camera camera = frame_mesh(edited);
    draw(renderer, camera);
    const NormalisedFrame before = renderer.frame();
    renderer.update_vertices(edited, every_vertex(edited));
    EXPECT_EQ(renderer.frame(), before) << what;
    SurfaceRenderer rebuilt;
    rebuilt.set_mesh(edited, build_surface_plans(edited, PlanOptions{}), before);
    expect_same_surface(draw(renderer, camera), draw(rebuilt, camera), bounding_box_diagonal(edited), what);
  }
}

// As the editor and the bench follow an operation (core/plans/surface_replanner.h): a move of every
// vertex re-planned and set as a change moves the frame; an extrusion after it, and its undo, draw as
// their meshes set anew.
TEST_F(MovedFrameTest, AMoveFollowedAsAChangeMovesTheFrameAndLaterOperationsFollowIt) {
  const CovarianceMesh mesh = make_sample("sphere", 3000);
  SurfaceReplanner replanner(mesh, PlanOptions{});
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh, replanner.shared_tables(), NormalisedFrame::of(mesh), replanner.last_change(), {});
  const Modelled moved = transform_vertices(mesh, {}, kTurnScaleAndMove);
  const Camera camera = frame_mesh(moved.mesh);
  draw(renderer, camera);
  const NormalisedFrame before = renderer.frame();
  draw(renderer, camera);
  const int captures = renderer.surface_cache().captures();
  ASSERT_GT(captures, 0);
  replanner.set_topology(moved.mesh, moved.vertex_origin);
  renderer.set_mesh(moved.mesh, replanner.shared_tables(), renderer.frame().following(moved.mesh),
                    replanner.last_change(), moved.vertex_origin);
  EXPECT_NEAR(renderer.frame().unit, 0.6 * before.unit, 1e-12 * before.unit);
  EXPECT_TRUE(renderer.frame().turned());
  SurfaceRenderer rebuilt;
  rebuilt.set_mesh(moved.mesh);
  expect_same_surface(draw(renderer, camera), draw(rebuilt, camera), bounding_box_diagonal(moved.mesh), "moved");
  EXPECT_EQ(renderer.surface_cache().captures(), captures) << "the move was evaluated again";

  const Modelled extruded = extrude_faces(moved.mesh, {1500, 1501}, 0.02 * bounding_box_diagonal(moved.mesh));
  replanner.set_topology(extruded.mesh, extruded.vertex_origin);
  renderer.set_mesh(extruded.mesh, replanner.shared_tables(), renderer.frame().following(extruded.mesh),
                    replanner.last_change(), extruded.vertex_origin);
  rebuilt.set_mesh(extruded.mesh);
  expect_same_surface(draw(renderer, camera), draw(rebuilt, camera), bounding_box_diagonal(extruded.mesh),
                      "then extruded");
  expect_same_corners(renderer, rebuilt, "then extruded");
  EXPECT_TRUE(renderer.frame().turned()) << "the extrusion took a frame of its own";
  // The Gaussians held were framed anew with the frame: the extrusion's unchanged ones are kept.
  EXPECT_EQ(renderer.surface_cache().captures(), captures) << "the extrusion was evaluated whole";

  const std::vector<int> back = inverse_origin(extruded.vertex_origin, moved.mesh.n_vertices());
  replanner.set_topology(moved.mesh, back);
  renderer.set_mesh(moved.mesh, replanner.shared_tables(), renderer.frame().following(moved.mesh),
                    replanner.last_change(), back);
  rebuilt.set_mesh(moved.mesh);
  expect_same_surface(draw(renderer, camera), draw(rebuilt, camera), bounding_box_diagonal(moved.mesh),
                      "the extrusion undone");
}

}  // namespace
}  // namespace gps
