// File → Simplify… in a real window under Xvfb, as a designer uses it on a dense icosphere:
// Ctrl+Shift+D, a typed vertex count, Enter to start (the replay waits for the background job),
// the result and its distance shown, Enter to apply; the saved mesh is the simplification of the
// input with that count, Ctrl+Z restores the input exactly, and Esc or Discard change nothing.
// Then File → Fit to… (Ctrl+Shift+F): the dense file is the target at first, Enter starts and Enter
// applies; the result is the core fit's. Screenshots kept in build/test-artefacts/EditorSimplify/.
#include <gtest/gtest.h>

#include "../support/editor_driver.h"
#include "core/fitting/face_triangles.h"
#include "core/fitting/limit_fit.h"
#include "core/fitting/mesh_simplification.h"
#include "core/io/mesh_io.h"
#include "core/modelling/samples.h"

namespace gps {
namespace {

using test::artefact;
using test::Events;

constexpr int kWidth = test::kWindowWidth, kHeight = test::kWindowHeight;

class EditorSimplify : public ::testing::Test {
protected:
  void SetUp() override {
    write_mesh(dir_.file("dense.ply"), make_sample("icosphere", 1280));
    dense_ = read_mesh(dir_.file("dense.ply"));
  }
  CovarianceMesh play(const Events& events, const std::string& screenshot) const {
    const auto r = test::play_editor(dir_, dir_.file("dense.ply"), events, kWidth, kHeight,
                                     "--save " + dir_.file("saved.ply") + " --screenshot " + artefact(screenshot));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return read_mesh(dir_.file("saved.ply"));
  }
  static Events simplified_to(const std::string& count) {
    Events e;
    e.key("ctrl+shift+d").wait(2).text(count).wait().key("enter").wait(3);
    return e;
  }
  static void expect_same(const CovarianceMesh& a, const CovarianceMesh& b) {
    ASSERT_EQ(a.n_vertices(), b.n_vertices());
    ASSERT_EQ(a.n_faces(), b.n_faces());
    for (size_t v = 0; v < a.n_vertices(); ++v) {
      EXPECT_EQ(a.mean(v), b.mean(v));
      EXPECT_EQ(a.covariance(v), b.covariance(v));
    }
  }
  test::TempDir dir_;
  CovarianceMesh dense_;
};

TEST_F(EditorSimplify, TypedCountStartedAppliedAndUndone) {
  Events shown = simplified_to("100");  // the result and its distance, before Apply
  const CovarianceMesh unchanged = play(shown, "simplify_result_shown.png");
  expect_same(unchanged, dense_);  // nothing changes until Apply

  Events applied = simplified_to("100");
  applied.key("enter").wait(3);
  const CovarianceMesh simplified = play(applied, "simplified.png");
  SimplifyOptions options;
  options.target_vertices = 100;
  expect_same(simplified, simplify_mesh(dense_, options).mesh);

  Events undone = applied;
  undone.key("ctrl+z").wait(3);
  expect_same(play(undone, "simplify_undone.png"), dense_);
}

TEST_F(EditorSimplify, TheSimplifiedMeshFittedToTheDenseFile) {
  Events fitted = simplified_to("100");
  fitted.key("enter").wait(3).key("ctrl+shift+f").wait(2).key("enter").wait(3).key("enter").wait(3);
  const CovarianceMesh saved = play(fitted, "fitted.png");
  SimplifyOptions options;
  options.target_vertices = 100;
  const CovarianceMesh coarse = simplify_mesh(dense_, options).mesh;
  std::vector<Vec3> targets;
  for (size_t v = 0; v < dense_.n_vertices(); ++v) targets.push_back(dense_.mean(v));
  // The fit turns the surface as the dense file's faces turn (core/fitting/face_triangles.h).
  const FitResult fit = fit_limit_surface(coarse, targets, FitOptions{}, smooth_vertex_normals(face_triangles(dense_)));
  EXPECT_LT(fit.iterations.back().error.rms, fit.iterations.front().error.rms);
  expect_same(saved, fit.mesh);
}

TEST_F(EditorSimplify, EscapeAndDiscardChangeNothing) {
  Events closed;
  closed.key("ctrl+shift+d").wait(2).key("escape").wait(2);
  expect_same(play(closed, "simplify_closed.png"), dense_);
  Events discarded = simplified_to("50");
  discarded.key("escape").wait(2).key("escape").wait(2);
  expect_same(play(discarded, "simplify_discarded.png"), dense_);
}

}  // namespace
}  // namespace gps
