// The editor's edits end to end, in a real window under Xvfb: each handle does one thing (scale one σ
// with the frame kept, turn with every σ kept, uniform scale, a move along one axis, a typed
// distance), proportional and mirrored edits, each one undo step that restores the file byte for
// byte; and screenshots of them, kept in build/test-artefacts/EditorEditing/.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "../support/editor_driver.h"
#include "core/io/mesh_io.h"
#include "core/modelling/samples.h"
#include "core/modelling/mesh_arrays.h"
#include "core/io/text_file.h"
#include "render/image/image_io.h"
#include "ui/editing/axis_handles.h"
#include "ui/editing/edit_reach.h"
#include "ui/editing/selection.h"
#include "ui/panels/view_options.h"
#include "view/picking.h"

namespace gps {
namespace {

using test::artefact;
using test::editor_view;
using test::Events;
using test::pixel_of;

constexpr int kWidth = test::kWindowWidth, kHeight = test::kWindowHeight;
constexpr int kVertex = 6;  // the cube's (1, 1, 1) corner, in front for the default camera

class EditorEditing : public ::testing::Test {
protected:
  void use_mesh(const CovarianceMesh& mesh) {
    write_mesh(dir_.file("original.ply"), mesh);
    original_ = read_mesh(dir_.file("original.ply"));  // the values the editor reads
  }
  void SetUp() override {
    CovarianceMesh mesh = make_sample("cube");
    const Mat3 r = Eigen::AngleAxisd(0.5, Vec3(1, -2, 0.5).normalized()).toRotationMatrix();
    mesh.covariances[kVertex] = r * Vec3(0.004, 0.02, 0.06).asDiagonal() * r.transpose();
    use_mesh(mesh);
  }
  // Plays the events, saves; then plays them again with Ctrl+Z and checks the file is the original.
  CovarianceMesh play_and_undo(const Events& events, int width = kWidth, int height = kHeight) {
    const auto r =
        test::play_editor(dir_, dir_.file("original.ply"), events, width, height, "--save " + dir_.file("edited.ply"));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    Events undo = events;
    undo.key("ctrl+z").wait();
    const auto u =
        test::play_editor(dir_, dir_.file("original.ply"), undo, width, height, "--save " + dir_.file("undone.ply"));
    EXPECT_EQ(u.exit_code, 0) << u.output;
    EXPECT_EQ(read_text_file(dir_.file("undone.ply")), read_text_file(dir_.file("original.ply")))
        << "one undo step restores the file";
    return read_mesh(dir_.file("edited.ply"));
  }
  void expect_others_unchanged(const CovarianceMesh& edited, const std::vector<int>& changed) {
    for (size_t v = 0; v < edited.n_vertices(); ++v) {
      if (std::find(changed.begin(), changed.end(), int(v)) != changed.end()) continue;
      EXPECT_EQ(edited.mean(v), original_.mean(v)) << v;
      EXPECT_EQ(edited.covariance(v), original_.covariance(v)) << v;
    }
  }
  // The gizmo of kVertex and its axis with the longest on-screen projection.
  std::pair<HandleFrame, int> gizmo() const {
    const Viewport view = editor_view(original_);
    const HandleFrame f = handle_frame(original_, kVertex, ViewOptions{}.draw.sigma_scale, view);
    int axis = 0;
    float longest = 0.0f;
    for (int a = 0; a < 3; ++a) {
      const float length = glm::length(pixel_of(view, f.end(a, 1)) - pixel_of(view, f.centre));
      if (length > longest) longest = length, axis = a;
    }
    return {f, axis};
  }
  test::TempDir dir_;
  CovarianceMesh original_;
};

TEST_F(EditorEditing, AScaleDragChangesExactlyOneSigmaAndKeepsTheFrame) {
  const auto [f, axis] = gizmo();
  const Viewport view = editor_view(original_);
  const Vec3 end = f.end(axis, 1);
  Events events;
  events.click(pixel_of(view, f.centre))
      .wait()
      .drag(pixel_of(view, end), pixel_of(view, f.centre + 0.6 * (end - f.centre)))
      .wait();
  const CovarianceMesh edited = play_and_undo(events);
  const EllipsoidAxes before = ellipsoid_axes(original_.covariance(kVertex));
  const Mat3& c = edited.covariance(kVertex);
  for (int k = 0; k < 3; ++k) {
    const Vec3 u = before.axes.col(k), image = c * u;
    EXPECT_LT((image - image.dot(u) * u).norm(), 1e-9 * image.norm()) << "the frame turned (axis " << k << ")";
    const double sigma = std::sqrt(u.dot(image));
    if (k == axis)
      EXPECT_NEAR(sigma, 0.6 * before.sigmas[k], 0.01 * before.sigmas[k]);
    else
      EXPECT_NEAR(sigma, before.sigmas[k], 1e-9 * before.sigmas[k]) << "axis " << k;
  }
  expect_others_unchanged(edited, {kVertex});
  EXPECT_EQ(edited.mean(kVertex), original_.mean(kVertex));
}

TEST_F(EditorEditing, ATurnKeepsEverySigmaAndShiftScalesAllThree) {
  const auto [f, axis] = gizmo();
  const Viewport view = editor_view(original_);
  const glm::vec2 start = pixel_of(view, f.end(axis, 1)), along = glm::normalize(start - pixel_of(view, f.centre));
  Events turn;
  turn.click(pixel_of(view, f.centre))
      .wait()
      .drag(start, start + 40.0f * glm::vec2(-along.y, along.x) + 10.0f * along)
      .wait();
  const CovarianceMesh turned = play_and_undo(turn);
  const auto sigmas = [](const Mat3& c) {
    return Vec3(Eigen::SelfAdjointEigenSolver<Mat3>(c).eigenvalues().cwiseSqrt());
  };
  const Vec3 before = sigmas(original_.covariance(kVertex));
  EXPECT_GT((turned.covariance(kVertex) - original_.covariance(kVertex)).norm(),
            1e-3 * original_.covariance(kVertex).norm());
  EXPECT_LT((sigmas(turned.covariance(kVertex)) - before).cwiseAbs().maxCoeff(), 1e-9 * before.maxCoeff());
  expect_others_unchanged(turned, {kVertex});

  const Vec3 end = f.end(axis, 1);
  Events uniform;
  uniform.click(pixel_of(view, f.centre))
      .wait()
      .drag(pixel_of(view, end), pixel_of(view, f.centre + 1.5 * (end - f.centre)), 6, "shift")
      .wait();
  const CovarianceMesh scaled = play_and_undo(uniform);
  const Vec3 ratio = sigmas(scaled.covariance(kVertex)).cwiseQuotient(before);
  EXPECT_NEAR(ratio[0], 1.5, 0.02);
  EXPECT_NEAR(ratio[1], ratio[0], 1e-9);
  EXPECT_NEAR(ratio[2], ratio[0], 1e-9);
  expect_others_unchanged(scaled, {kVertex});
}

TEST_F(EditorEditing, AMoveAlongOneAxisChangesOneCoordinateAndATypedDistanceIsExact) {
  const auto [f, axis] = gizmo();
  const Viewport view = editor_view(original_);
  const glm::vec2 centre = pixel_of(view, f.centre);
  Events along_z;
  along_z.click(centre)
      .wait()
      .press(centre)
      .move(centre + glm::vec2(4, -6))
      .key("z")
      .move(centre + glm::vec2(10, -40))
      .release(centre + glm::vec2(10, -40))
      .wait();
  const CovarianceMesh moved = play_and_undo(along_z);
  EXPECT_GT(std::abs(moved.mean(kVertex).z() - original_.mean(kVertex).z()), 0.05);
  EXPECT_EQ(moved.mean(kVertex).x(), original_.mean(kVertex).x());
  EXPECT_EQ(moved.mean(kVertex).y(), original_.mean(kVertex).y());
  EXPECT_EQ(moved.covariance(kVertex), original_.covariance(kVertex));
  expect_others_unchanged(moved, {kVertex});

  Events typed;
  typed.click(centre)
      .wait()
      .press(centre)
      .move(centre + glm::vec2(5, 5))
      .key("y")
      .text("-0.25")
      .key("enter")
      .release(centre + glm::vec2(5, 5))
      .wait();
  const CovarianceMesh exact = play_and_undo(typed);
  EXPECT_NEAR(exact.mean(kVertex).y() - original_.mean(kVertex).y(), -0.25, 1e-6);  // the file keeps floats
  EXPECT_EQ(exact.mean(kVertex).x(), original_.mean(kVertex).x());
  EXPECT_EQ(exact.mean(kVertex).z(), original_.mean(kVertex).z());
}

// A scale by -1 along x of the whole cube (A, S X -1 Enter) mirrors it and reverses its faces with
// it, as Blender does: the surface stays outward (the signed volume stays positive), one undo step.
TEST_F(EditorEditing, AMirrorScaleReversesTheFacesSoTheSurfaceStaysOutward) {
  const auto signed_volume = [](const CovarianceMesh& m) {
    const MeshArrays a = arrays_of(m);
    double six_volume = 0;
    for (const std::vector<int>& face : a.faces)
      for (size_t k = 1; k + 1 < face.size(); ++k)
        six_volume += a.means[size_t(face[0])].dot(a.means[size_t(face[k])].cross(a.means[size_t(face[k + 1])]));
    return six_volume / 6;
  };
  Events mirror;
  mirror.move(glm::vec2(kWidth / 2, kHeight / 2)).key("a").wait().key("s").key("x").text("-1").key("enter").wait();
  const CovarianceMesh m = play_and_undo(mirror);
  ASSERT_EQ(m.n_vertices(), original_.n_vertices());
  double centre_x = 0;  // the pivot: the selection's median point
  for (size_t v = 0; v < original_.n_vertices(); ++v)
    centre_x += original_.mean(v).x() / double(original_.n_vertices());
  for (size_t v = 0; v < m.n_vertices(); ++v) EXPECT_NEAR(m.mean(v).x(), 2 * centre_x - original_.mean(v).x(), 1e-6);
  const double volume = signed_volume(original_);
  ASSERT_GT(volume, 0);
  EXPECT_NEAR(signed_volume(m), volume, 1e-5 * volume);
}

TEST_F(EditorEditing, AMirroredEditChangesTheMirrorVertexByTheMirroredAmount) {
  const auto [f, axis] = gizmo();
  const Viewport view = editor_view(original_);
  const glm::vec2 centre = pixel_of(view, f.centre);
  int partner = -1;
  for (size_t v = 0; v < original_.n_vertices(); ++v)
    if ((original_.mean(v) -
         Vec3(-original_.mean(kVertex).x(), original_.mean(kVertex).y(), original_.mean(kVertex).z()))
            .norm() < 1e-9)
      partner = int(v);
  ASSERT_GE(partner, 0);
  Events events;
  events.key("shift+m")
      .click(centre)
      .wait()
      .press(centre)
      .move(centre + glm::vec2(5, 5))
      .key("x")
      .text("0.3")
      .key("enter")
      .release(centre)
      .wait();
  const CovarianceMesh edited = play_and_undo(events);
  EXPECT_NEAR(edited.mean(kVertex).x() - original_.mean(kVertex).x(), 0.3, 1e-6);
  EXPECT_NEAR(edited.mean(size_t(partner)).x() - original_.mean(size_t(partner)).x(), -0.3, 1e-6);
  EXPECT_EQ(edited.mean(size_t(partner)).y(), original_.mean(size_t(partner)).y());
  expect_others_unchanged(edited, {kVertex, partner});
}

// The vertex of `mesh` nearest the camera (picked by a click on its pixel).
int front_vertex(const CovarianceMesh& mesh, const Viewport& view) {
  const Vec3 eye = to_vec(view.camera.eye());
  int best = 0;
  for (size_t v = 1; v < mesh.n_vertices(); ++v)
    if ((mesh.mean(v) - eye).norm() < (mesh.mean(size_t(best)) - eye).norm()) best = int(v);
  return best;
}

TEST_F(EditorEditing, AProportionalEditMovesTheVerticesInsideTheRadiusByTheFalloff) {
  use_mesh(make_sample("sphere", 1536));
  const Viewport view = editor_view(original_);
  const int vertex = front_vertex(original_, view);
  const glm::vec2 centre = pixel_of(view, original_.mean(size_t(vertex)));
  ASSERT_EQ(pick_vertex(view.camera, view.width, view.height, centre, original_, 8.0f), vertex);
  Events events;
  events.key("o")
      .click(centre)
      .wait()
      .press(centre)
      .move(centre + glm::vec2(3, 6))
      .key("z")
      .text("0.3")
      .key("enter")
      .release(centre)
      .wait();
  const CovarianceMesh edited = play_and_undo(events);
  const double radius = 0.1 * bounding_box_diagonal(original_);  // the editor's default radius
  int inside = 0;
  for (size_t v = 0; v < original_.n_vertices(); ++v) {
    const double d = (original_.mean(v) - original_.mean(size_t(vertex))).norm();
    const double w = d < radius ? falloff_weight(Falloff::smooth, d / radius) : 0.0;
    const Vec3 expected = original_.mean(v) + Vec3(0, 0, w * 0.3);
    EXPECT_LT((edited.mean(v) - expected).norm(), 1e-6) << "vertex " << v << " at " << d / radius << " radii";
    EXPECT_EQ(edited.covariance(v), original_.covariance(v));
    if (w > 0) {
      ++inside;
    } else {
      EXPECT_EQ(edited.mean(v), original_.mean(v)) << v;
    }
  }
  EXPECT_GT(inside, 10);
}

TEST_F(EditorEditing, SettingsAreKeptInTheConfigurationFolder) {
  Events toggle;
  toggle.key("shift+e").wait();
  ASSERT_EQ(test::play_editor(dir_, dir_.file("original.ply"), toggle, kWidth, kHeight, "").exit_code, 0);
  ASSERT_EQ(test::play_editor(dir_, dir_.file("original.ply"), Events().wait(), kWidth, kHeight, "").exit_code, 0);
  const nlohmann::json settings = nlohmann::json::parse(read_text_file(dir_.file("gpsurf/settings.json")));
  EXPECT_TRUE(settings.at("ellipsoids").get<bool>());  // set by the first run, kept by the second
  EXPECT_TRUE(std::filesystem::exists(dir_.file("gpsurf/imgui.ini")));
  EXPECT_FALSE(std::filesystem::exists(dir_.file("gpsurf/recent.txt"))) << "--play runs are not recent files";
}

// Screenshots: a 12-vertex selection with one gizmo and mixed values in the
// Inspector; the torus framed beside the panels (Home) at 900 × 600.
TEST_F(EditorEditing, ScreenshotsOfAMultiSelectionAndOfFramingBesideThePanels) {
  use_mesh(make_sample("torus"));
  const Viewport view = editor_view(original_);
  // A box from a corner on the torus, grown until it holds 12 vertices, seen or hidden.
  const auto [corner, side] = test::box_holding(view, glm::vec2(205.0f, 318.0f), original_, 12);
  ASSERT_EQ(vertices_in_box(view.camera, view.width, view.height, corner, corner + side, original_).size(), 12u);
  Events events;
  events.key("alt+z").drag(corner, corner + side, 8).wait();  // select through: the hidden ones too
  const auto r = test::play_editor(dir_, dir_.file("original.ply"), events.wait(), kWidth, kHeight,
                                   "--screenshot " + artefact("multi_selection.png"));
  ASSERT_EQ(r.exit_code, 0) << r.output;

  Events home;
  home.wait(3).key("home").wait(3);
  const auto framed =
      test::play_editor(dir_, dir_.file("original.ply"), home, 900, 600,
                        "--screenshot " + artefact("torus_framed.png") + " --stats " + dir_.file("stats.json"));
  ASSERT_EQ(framed.exit_code, 0) << framed.output;
  // The surface (warm clay) lies left of the panels (where the layout kept from the 1024-pixel run
  // put them: the free region's right edge, 8 pixels before them).
  const float panels = nlohmann::json::parse(read_text_file(dir_.file("stats.json")))["free_region"][2];
  EXPECT_LT(panels, 900.0f - 200.0f);
  const Image shot = read_image(artefact("torus_framed.png"));
  int left = 0, under_panels = 0;
  for (int y = 40; y < shot.height - 30; ++y)
    for (int x = 0; x < shot.width; ++x) {
      const bool warm = shot.at(x, y, 0) - shot.at(x, y, 2) > 0.06f && shot.at(x, y, 0) > shot.at(x, y, 1);
      (float(x) < panels ? left : under_panels) += warm;
    }
  EXPECT_GT(left, 5000);
  EXPECT_LT(under_panels, left / 50) << "the torus is under the panels";
}

// The edit-to-frame figure: a proportional drag over about 1,000 vertices of the 100k sphere, its
// edit-to-frame time in the statistics (and a screenshot of the drag with its radius).
TEST_F(EditorEditing, AProportionalDragOnTheLargeSphere) {
  use_mesh(make_sample("sphere", 100000));
  const Viewport view = editor_view(original_);
  const int vertex = front_vertex(original_, view);
  const glm::vec2 centre = pixel_of(view, original_.mean(size_t(vertex)));
  Events events;
  events.key("o").click(centre).wait().press(centre).move(centre + glm::vec2(1, -4)).key("y").scroll(centre, -4.0f);
  for (int i = 1; i <= 12; ++i) events.move(centre + glm::vec2(1.0f, -4.0f - 3.0f * float(i))).wait(1);
  events.wait();
  const auto r = test::play_editor(
      dir_, dir_.file("original.ply"), events, kWidth, kHeight,
      "--screenshot " + artefact("proportional_sphere.png") + " --stats " + artefact("proportional_sphere.json"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json stats = nlohmann::json::parse(read_text_file(artefact("proportional_sphere.json")));
  EXPECT_GT(stats.at("last_edit_vertices").get<int>(), 500);
  EXPECT_LT(stats.at("last_edit_vertices").get<int>(), 2000);
  EXPECT_GT(stats.at("edits").get<int>(), 5);
}

}  // namespace
}  // namespace gps
