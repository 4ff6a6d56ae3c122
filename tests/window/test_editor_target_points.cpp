// View → Show target points… in a real window under Xvfb: a coarse icosphere opened, a target of
// points in clusters (one on the limit surface, one floating off it by d, one by about half of d,
// one on the surface's far side) typed into the file dialog; the screenshot shows the first cluster
// blue, the second red and the third yellow on the distance ramp (its end the 99th percentile, d),
// and none of the hidden one. Shift+T hides them; the target shown is kept for the mesh file
// (settings.json) and comes back when it is opened again, not after it was hidden. Screenshots
// kept in build/test-artefacts/EditorTargetPoints/.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <Eigen/Geometry>

#include "../support/editor_driver.h"
#include "core/fitting/surface_distance.h"
#include "core/io/mesh_io.h"
#include "core/modelling/samples.h"
#include "render/image/image_io.h"
#include "render/overlays/distance_ramp.h"

namespace gps {
namespace {

using test::artefact;
using test::Events;

constexpr int kWidth = test::kWindowWidth, kHeight = test::kWindowHeight;

struct Cluster {
  Vec3 centre;      // the point of the cluster nearest its direction (offset as the cluster is)
  glm::vec3 colour;  // the colour its points should show
};

class EditorTargetPoints : public ::testing::Test {
protected:
  void SetUp() override {
    coarse_ = make_sample("icosphere", 80);
    write_mesh(dir_.file("coarse.ply"), coarse_);
    view_ = test::editor_view(coarse_);
    // Directions from the centre: towards the eye, and the screen's right and up.
    Vec3 centre = Vec3::Zero();
    for (const Vec3& p : vertex_means(coarse_)) centre += p / double(coarse_.n_vertices());
    const glm::dvec3 eye = view_.camera.eye_double();
    const Vec3 e = (Vec3(eye.x, eye.y, eye.z) - centre).normalized();
    const Vec3 right = Vec3::UnitY().cross(e).normalized(), up = e.cross(right);
    const double d = 0.08 * bounding_box_diagonal(vertex_means(coarse_));
    struct Kind {
      Vec3 direction;
      double offset;
    };
    const Kind kinds[] = {{(e + 0.55 * right).normalized(), 0.0},
                          {(e - 0.55 * right).normalized(), d},
                          {(e + 0.55 * up).normalized(), 0.55 * d},
                          {-e, 0.0}};
    const TriangleMesh surface = limit_surface_triangles(coarse_, 5).triangles;
    std::string points;
    size_t count = 0;
    for (int k = 0; k < 4; ++k) {
      double nearest = -1.0;
      for (const Vec3& p : surface.positions) {
        const Vec3 n = (p - centre).normalized();
        const double alignment = n.dot(kinds[k].direction);
        if (alignment < std::cos(0.14)) continue;
        const Vec3 q = p + kinds[k].offset * n;
        points += std::to_string(q.x()) + " " + std::to_string(q.y()) + " " + std::to_string(q.z()) + "\n";
        ++count;
        if (alignment > nearest) nearest = alignment, clusters_[k].centre = q;
      }
    }
    clusters_[0].colour = ramp_colour(0.0f);
    clusters_[1].colour = ramp_colour(1.0f);
    clusters_[2].colour = ramp_colour(0.55f);
    std::ofstream(dir_.file("target.ply")) << "ply\nformat ascii 1.0\nelement vertex " << count
                                           << "\nproperty float x\nproperty float y\nproperty float z\nend_header\n"
                                           << points;
  }
  Image play(const Events& events, const std::string& screenshot) const {
    const auto r = test::play_editor(dir_, dir_.file("coarse.ply"), events, kWidth, kHeight,
                                     "--screenshot " + artefact(screenshot));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return read_image(artefact(screenshot));
  }
  // Whether a pixel within 3 of where `p` projects has `colour` (a point's centre, inside its dark rim).
  bool shows(const Image& shot, const Vec3& p, const glm::vec3& colour) const {
    const glm::vec2 at = test::pixel_of(view_, p);
    for (int y = int(at.y) - 3; y <= int(at.y) + 3; ++y)
      for (int x = int(at.x) - 3; x <= int(at.x) + 3; ++x) {
        if (x < 0 || y < 0 || x >= shot.width || y >= shot.height) continue;
        const glm::vec3 c(shot.at(x, y, 0), shot.at(x, y, 1), shot.at(x, y, 2));
        if (glm::length(c - colour) < 0.1f) return true;
      }
    return false;
  }
  // Whether any of the ramp's colours shows near where `p` projects.
  bool shows_any_point(const Image& shot, const Vec3& p) const {
    for (int i = 0; i <= 20; ++i)
      if (shows(shot, p, ramp_colour(float(i) / 20.0f))) return true;
    return false;
  }
  static Events shown_by_dialog(const std::string& path) {
    Events e;
    e.key("ctrl+shift+t").wait(2).text(path).wait().key("enter").wait(3);
    return e;
  }

  test::TempDir dir_;
  CovarianceMesh coarse_;
  Viewport view_;
  Cluster clusters_[4];
};

TEST_F(EditorTargetPoints, ColouredByDistanceHiddenBehindAndToggled) {
  const Image shown = play(shown_by_dialog(dir_.file("target.ply")), "target_points.png");
  EXPECT_TRUE(shows(shown, clusters_[0].centre, clusters_[0].colour)) << "the points on the surface are not blue";
  EXPECT_TRUE(shows(shown, clusters_[1].centre, clusters_[1].colour)) << "the farthest points are not red";
  EXPECT_TRUE(shows(shown, clusters_[2].centre, clusters_[2].colour)) << "the points halfway out are not yellow";
  EXPECT_FALSE(shows_any_point(shown, clusters_[3].centre)) << "the points behind the surface show through it";

  Events hidden = shown_by_dialog(dir_.file("target.ply"));
  hidden.key("shift+t").wait(3);
  const Image off = play(hidden, "target_points_hidden.png");
  for (int k = 0; k < 3; ++k) EXPECT_FALSE(shows_any_point(off, clusters_[k].centre)) << "cluster " << k;
}

TEST_F(EditorTargetPoints, KeptForTheMeshFileUntilHidden) {
  play(shown_by_dialog(dir_.file("target.ply")), "target_points_first.png");
  Events none;
  none.wait(2);
  const Image reopened = play(none, "target_points_reopened.png");
  EXPECT_TRUE(shows(reopened, clusters_[1].centre, clusters_[1].colour)) << "the target was not kept for the file";

  Events hide;
  hide.wait(2).key("shift+t").wait(2);
  play(hide, "target_points_hidden_then.png");
  const Image forgotten = play(none, "target_points_forgotten.png");
  EXPECT_FALSE(shows_any_point(forgotten, clusters_[1].centre)) << "a hidden target came back";
}

}  // namespace
}  // namespace gps
