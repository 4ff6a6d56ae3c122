#include "ui/document/edit_history.h"

#include <gtest/gtest.h>

#include <random>

#include "core/modelling/samples.h"

namespace gps {
namespace {

// Any sequence of edits, undone step by step, restores the exact earlier Gaussians; redo replays them.
TEST(EditHistory, UndoRestoresExactlyAndRedoReplays) {
  CovarianceMesh mesh = make_sample("valence5");
  const CovarianceMesh original = mesh;
  EditHistory history;
  std::mt19937 rng(4);
  std::uniform_int_distribution<int> vertex(0, int(mesh.n_vertices()) - 1);
  std::vector<CovarianceMesh> states = {mesh};
  for (int step = 0; step < 20; ++step) {
    const std::vector<int> vertices = {vertex(rng), vertex(rng)};
    VertexEdit e = EditHistory::begin(mesh, vertices);
    for (const int v : vertices) {
      mesh.covariances[size_t(v)] *= 0.7 + 0.01 * step;
      mesh.set_mean(size_t(v), mesh.mean(size_t(v)) + Vec3(0.01, -0.02, 0.003 * step));
    }
    history.commit(std::move(e), mesh);
    states.push_back(mesh);
  }
  for (int step = 20; step > 0; --step) {
    ASSERT_TRUE(history.can_undo());
    history.undo(mesh);
    for (size_t i = 0; i < mesh.n_vertices(); ++i) {
      EXPECT_EQ(mesh.covariance(i), states[size_t(step - 1)].covariance(i));
      EXPECT_EQ(mesh.mean(i), states[size_t(step - 1)].mean(i));
    }
  }
  EXPECT_FALSE(history.can_undo());
  for (size_t i = 0; i < mesh.n_vertices(); ++i) EXPECT_EQ(mesh.covariance(i), original.covariance(i));
  for (int step = 1; step <= 20; ++step) history.redo(mesh);
  for (size_t i = 0; i < mesh.n_vertices(); ++i) EXPECT_EQ(mesh.covariance(i), states.back().covariance(i));
}

TEST(EditHistory, DirtyFlagFollowsTheSavedState) {
  CovarianceMesh mesh = make_sample("cube");
  EditHistory history;
  EXPECT_FALSE(history.dirty());
  VertexEdit e = EditHistory::begin(mesh, {0});
  mesh.covariances[0] *= 2.0;
  history.commit(std::move(e), mesh);
  EXPECT_TRUE(history.dirty());
  history.mark_saved();
  EXPECT_FALSE(history.dirty());
  history.undo(mesh);
  EXPECT_TRUE(history.dirty());
  history.redo(mesh);
  EXPECT_FALSE(history.dirty());
  history.undo(mesh);
  VertexEdit f = EditHistory::begin(mesh, {1});  // a new branch: the saved state is unreachable
  mesh.covariances[1] *= 3.0;
  history.commit(std::move(f), mesh);
  EXPECT_TRUE(history.dirty());
  history.undo(mesh);
  EXPECT_TRUE(history.dirty());
}

// last_step names the step applied last: a new one for every step pushed, the earlier one after an
// undo, the same again after a redo, and never a number a dropped branch had.
TEST(EditHistory, TheLastStepHasANumberNoOtherStepGets) {
  CovarianceMesh mesh = make_sample("cube");
  EditHistory history;
  EXPECT_EQ(history.last_step(), 0u);
  const auto edit = [&](int v) {
    VertexEdit e = EditHistory::begin(mesh, {v});
    mesh.covariances[size_t(v)] *= 2.0;
    history.commit(std::move(e), mesh);
    return history.last_step();
  };
  const auto first = edit(0), second = edit(1);
  EXPECT_NE(first, 0u);
  EXPECT_NE(second, first);
  history.undo(mesh);
  EXPECT_EQ(history.last_step(), first);
  history.redo(mesh);
  EXPECT_EQ(history.last_step(), second);
  history.undo(mesh);
  const auto branch = edit(2);  // drops `second`
  EXPECT_NE(branch, second);
  EXPECT_NE(branch, first);
  history.undo(mesh);
  history.undo(mesh);
  EXPECT_EQ(history.last_step(), 0u);
}

}  // namespace
}  // namespace gps
