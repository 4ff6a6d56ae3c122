#include "ui/document/editor_document.h"

#include <gtest/gtest.h>

#include <functional>

#include "../support/temp_dir.h"
#include "core/support/error.h"
#include "core/io/mesh_io.h"
#include "core/io/text_file.h"
#include "core/modelling/samples.h"
#include "core/modelling/affine_transform.h"
#include "core/modelling/delete_elements.h"
#include "core/modelling/extrude.h"
#include "core/modelling/loop_cut.h"
#include "core/modelling/merge_vertices.h"
#include "core/modelling/split_faces.h"

namespace gps {
namespace {

TEST(EditorDocument, AMalformedFileKeepsTheCurrentMesh) {
  const test::TempDir dir;
  write_mesh(dir.file("good.ply"), make_sample("cube"));
  const std::string bad =
      dir.write("bad.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n1\n2\n");
  EditorDocument doc;
  doc.open(dir.file("good.ply"));
  doc.begin_edit();
  doc.set_covariance(1, 3.0 * doc.mesh().covariance(1));
  doc.commit_edit();
  try {
    doc.open(bad);
    FAIL() << "a malformed file opened";
  } catch (const Error& x) {
    EXPECT_NE(std::string(x.what()).find("bad.ply"), std::string::npos);
    EXPECT_EQ(std::string(x.what()).find('\n'), std::string::npos);
  }
  EXPECT_EQ(doc.mesh().n_vertices(), 8u);
  EXPECT_EQ(doc.mesh().covariance(1), 3.0 * make_sample("cube").covariance(1));
  EXPECT_TRUE(doc.dirty());
  EXPECT_EQ(doc.display_name(), "good.ply");
}

TEST(EditorDocument, SavingClearsDirtyAndKeepsTheFormat) {
  const test::TempDir dir;
  write_mesh(dir.file("b.ply"), make_sample("cube"), true);
  EditorDocument doc;
  doc.open(dir.file("b.ply"));
  EXPECT_TRUE(doc.can_save_in_place());
  doc.begin_edit();
  doc.set_covariance(2, 0.5 * doc.mesh().covariance(2));
  doc.commit_edit();
  EXPECT_TRUE(doc.dirty());
  doc.save(doc.ply_path());
  EXPECT_FALSE(doc.dirty());
  EXPECT_NE(read_text_file(dir.file("b.ply")).find("format binary_little_endian"), std::string::npos);
  EXPECT_EQ(read_mesh(dir.file("b.ply")).covariance(2), 0.5 * make_sample("cube").covariance(2));
  // Undo after saving is an unsaved change again; redo returns to the saved state.
  doc.undo();
  EXPECT_TRUE(doc.dirty());
  doc.redo();
  EXPECT_FALSE(doc.dirty());
}

TEST(EditorDocument, SamplesAndImportsAskWhereToSave) {
  const test::TempDir dir;
  EditorDocument doc;
  doc.open_sample("cube");
  EXPECT_FALSE(doc.can_save_in_place());
  EXPECT_EQ(doc.display_name(), "sample cube");
  write_mesh(dir.file("plain.obj"), make_sample("cube"));
  doc.open(dir.file("plain.obj"));
  EXPECT_FALSE(doc.can_save_in_place());  // an OBJ keeps no covariances
  doc.save(dir.file("edited.ply"));
  EXPECT_TRUE(doc.can_save_in_place());
  EXPECT_EQ(doc.display_name(), "edited.ply");
  EXPECT_EQ(read_mesh(dir.file("edited.ply")).n_vertices(), 8u);
  EXPECT_EQ(read_text_file(dir.file("edited.ply")).rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u);
}

TEST(EditorDocument, AnAsciiPlyStaysText) {
  const test::TempDir dir;
  write_mesh(dir.file("a.ply"), make_sample("cube"), false);
  EditorDocument doc;
  doc.open(dir.file("a.ply"));
  doc.save(doc.ply_path());
  EXPECT_EQ(read_text_file(dir.file("a.ply")).rfind("ply\nformat ascii 1.0\n", 0), 0u);
  doc.open_sample("cube");
  doc.save(dir.file("sample.ply"));
  EXPECT_EQ(read_text_file(dir.file("sample.ply")).rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u);
}

TEST(EditorDocument, AFailedSaveKeepsTheFileAndTheState) {
  const test::TempDir dir;
  EditorDocument doc;
  doc.open_sample("cube");
  doc.begin_edit();
  doc.set_covariance(0, 2.0 * doc.mesh().covariance(0));
  doc.commit_edit();
  EXPECT_THROW(doc.save(dir.file("missing-folder/x.ply")), Error);
  EXPECT_TRUE(doc.dirty());
  EXPECT_FALSE(doc.can_save_in_place());
}

// One transaction: every set is recorded for the GPU without a separate mark, the start values are
// readable during the edit, a commit is one undo step (none when nothing changed), cancel restores.
TEST(EditorDocument, AnEditIsOneTransaction) {
  EditorDocument doc;
  doc.open_sample("cube");
  const CovarianceMesh original = doc.mesh();
  doc.take_changed();
  doc.begin_edit();
  doc.set_mean(3, Vec3(1, 2, 3));
  doc.set_mean(3, Vec3(4, 5, 6));
  doc.set_covariance(5, 2.0 * original.covariance(5));
  EXPECT_EQ(doc.take_changed(), (std::vector<int>{3, 5}));
  EXPECT_EQ(doc.start_mean(3), original.mean(3));
  EXPECT_EQ(doc.start_covariance(5), original.covariance(5));
  EXPECT_EQ(doc.mesh().mean(3), Vec3(4, 5, 6));
  EXPECT_FALSE(doc.can_undo());  // not in the middle of an edit
  EXPECT_TRUE(doc.commit_edit());
  EXPECT_TRUE(doc.dirty());
  doc.undo();
  EXPECT_EQ(doc.take_changed(), (std::vector<int>{3, 5}));
  EXPECT_EQ(doc.mesh().mean(3), original.mean(3));
  EXPECT_EQ(doc.mesh().covariance(5), original.covariance(5));
  EXPECT_FALSE(doc.dirty());
  EXPECT_FALSE(doc.can_undo());
  // Setting a vertex back to its start value is no step.
  doc.begin_edit();
  doc.set_mean(1, Vec3(9, 9, 9));
  doc.set_mean(1, original.mean(1));
  EXPECT_FALSE(doc.commit_edit());
  EXPECT_FALSE(doc.can_undo());
  // Cancel restores and records the vertices for the GPU.
  doc.take_changed();
  doc.begin_edit();
  doc.set_covariance(2, 3.0 * original.covariance(2));
  doc.cancel_edit();
  EXPECT_EQ(doc.mesh().covariance(2), original.covariance(2));
  EXPECT_EQ(doc.take_changed(), std::vector<int>{2});
  EXPECT_FALSE(doc.dirty());
}

// Two meshes alike in everything the file keeps: vertices, faces (corner order), Gaussians.
void expect_same_mesh(const CovarianceMesh& a, const CovarianceMesh& b) {
  ASSERT_EQ(a.n_vertices(), b.n_vertices());
  ASSERT_EQ(a.n_faces(), b.n_faces());
  for (size_t v = 0; v < a.n_vertices(); ++v) {
    EXPECT_EQ(a.mean(v), b.mean(v)) << v;
    EXPECT_EQ(a.covariance(v), b.covariance(v)) << v;
  }
  for (size_t f = 0; f < a.n_faces(); ++f) {
    const std::span<const int> fa = a.face(f), fb = b.face(f);
    EXPECT_EQ(std::vector<int>(fa.begin(), fa.end()), std::vector<int>(fb.begin(), fb.end())) << "face " << f;
  }
}

// A modelling operation is one undo step that restores the mesh exactly, with the selection before
// it; vertex edits before and after it undo and redo across it; the dirty state follows the history.
TEST(EditorDocument, AModellingOperationIsOneExactUndoStep) {
  test::TempDir dir;
  EditorDocument doc;
  doc.open_sample("cube");
  doc.save(dir.file("cube.ply"));
  const CovarianceMesh original = doc.mesh();
  doc.begin_edit();
  doc.set_mean(6, Vec3(1.5, 1, 1));
  ASSERT_TRUE(doc.commit_edit());
  const CovarianceMesh moved = doc.mesh();
  const Modelled cut = loop_cut(doc.mesh(), 0, 4, 2);
  doc.apply(cut, {{6}});
  EXPECT_TRUE(doc.take_changed().empty()) << "a new topology is rebuilt, not updated";
  expect_same_mesh(doc.mesh(), cut.mesh);
  doc.begin_edit();
  doc.set_mean(int(cut.mesh.n_vertices()) - 1, Vec3(0, 0, 3));
  ASSERT_TRUE(doc.commit_edit());

  EXPECT_FALSE(doc.undo().has_value()) << "a vertex edit restores vertices";
  expect_same_mesh(doc.mesh(), cut.mesh);
  const auto selection = doc.undo();
  ASSERT_TRUE(selection.has_value());
  EXPECT_EQ(selection->vertices, std::vector<int>{6});
  expect_same_mesh(doc.mesh(), moved);
  doc.undo();
  expect_same_mesh(doc.mesh(), original);
  EXPECT_FALSE(doc.dirty());
  doc.save(dir.file("again.ply"));
  EXPECT_EQ(read_text_file(dir.file("again.ply")), read_text_file(dir.file("cube.ply")));

  doc.redo();
  const auto redone = doc.redo();
  ASSERT_TRUE(redone.has_value());
  EXPECT_EQ(redone->vertices, cut.selection);
  expect_same_mesh(doc.mesh(), cut.mesh);
  EXPECT_TRUE(doc.dirty());
}

// The selection an operation started from comes back with its undo as it was: edges held in edge
// mode stay edges (not every edge between their ends); the redo selects the result's vertices.
TEST(EditorDocument, UndoGivesBackTheEdgesTheSelectionHeld) {
  EditorDocument doc;
  doc.open_sample("cube");
  const SelectionRecord edges{{2, 3, 6, 7}, {{2, 3}, {6, 7}}, true};
  const Modelled cut = loop_cut(doc.mesh(), 0, 4, 2);
  doc.apply(cut, edges);
  EXPECT_EQ(doc.undo(), edges);
  const auto redone = doc.redo();
  ASSERT_TRUE(redone.has_value());
  EXPECT_EQ(*redone, SelectionRecord{cut.selection});
}

// Undo and redo of an operation say where the restored mesh's vertices were in the mesh they replace
// (the plans follow the change): a delete's origins on redo, their inverse on undo.
TEST(EditorDocument, UndoAndRedoGiveTheVerticesOrigins) {
  EditorDocument doc;
  doc.open_sample("cube");
  const Modelled deleted = delete_vertices(doc.mesh(), {2});
  ASSERT_EQ(deleted.vertex_origin, (std::vector<int>{0, 1, 3, 4, 5, 6, 7}));
  doc.apply(deleted, {{2}});
  ASSERT_TRUE(doc.undo().has_value());
  EXPECT_EQ(doc.replaced_origin(), (std::vector<int>{0, 1, -1, 2, 3, 4, 5, 6}));
  ASSERT_TRUE(doc.redo().has_value());
  EXPECT_EQ(doc.replaced_origin(), deleted.vertex_origin);
}

// An extrusion and the move that follows it undo as one step; a tool cancelled after its operation
// leaves no step to redo.
TEST(EditorDocument, AMoveFoldsIntoTheOperationBeforeIt) {
  EditorDocument doc;
  doc.open_sample("cube");
  const CovarianceMesh original = doc.mesh();
  const Modelled extruded = extrude_vertices(doc.mesh(), {4, 5, 6, 7}, Vec3::Zero());
  doc.apply(extruded, {{4, 5, 6, 7}});
  doc.begin_edit();
  for (const int v : extruded.selection) doc.set_mean(v, doc.mesh().mean(size_t(v)) + Vec3(0, 0, 1));
  EXPECT_TRUE(doc.commit_edit_into_last_operation({extruded.selection}));
  const CovarianceMesh result = doc.mesh();
  doc.undo();
  expect_same_mesh(doc.mesh(), original);
  EXPECT_FALSE(doc.can_undo());
  EXPECT_FALSE(doc.dirty());
  doc.redo();
  expect_same_mesh(doc.mesh(), result);

  doc.apply(extruded, {});
  doc.discard_last_operation();
  expect_same_mesh(doc.mesh(), result);
  EXPECT_FALSE(doc.can_redo());
}

// An operation's undo step is made after it (settle_history, an undo, the next step), from the mesh
// before it and the mesh after it as it then is: a move folded in first, or a vertex edit committed
// on top as its own step, each undo and redo restores its mesh exactly; a save before a folded move
// is not the mesh after it.
TEST(EditorDocument, AnOperationsUndoStepMadeLaterRestoresExactly) {
  test::TempDir dir;
  EditorDocument doc;
  doc.open_sample("sphere");
  const CovarianceMesh original = doc.mesh();
  const Modelled extruded = extrude_faces(doc.mesh(), {3}, 0.1);
  doc.apply(extruded, {{0}});
  doc.settle_history();
  const size_t mesh_bytes = doc.mesh().n_vertices() * (sizeof(Vec3) + sizeof(Mat3));
  EXPECT_LT(doc.history_bytes(), mesh_bytes / 4) << "a settled step holds what the operation changed";
  const Modelled cut = loop_cut(doc.mesh(), doc.mesh().face(0)[0], doc.mesh().face(0)[1], 1);
  doc.apply(cut, {{1}});
  EXPECT_GT(doc.history_bytes(), mesh_bytes) << "a waiting step holds the mesh before it";
  doc.begin_edit();
  const int moved = int(cut.mesh.n_vertices()) - 1;
  doc.set_mean(moved, Vec3(0.1, 0.2, 2.0));
  ASSERT_TRUE(doc.commit_edit());  // its own step: the cut's deltas take the mesh before it
  const CovarianceMesh edited = doc.mesh();
  const Modelled deleted = delete_faces(doc.mesh(), {1});
  doc.apply(deleted, {{2}});
  doc.save(dir.file("saved.ply"));
  doc.begin_edit();
  doc.set_mean(0, doc.mesh().mean(0) + Vec3(0, 0, 0.5));
  ASSERT_TRUE(doc.commit_edit_into_last_operation({{0}}));
  EXPECT_TRUE(doc.dirty()) << "the move folded in after the save";
  const CovarianceMesh last = doc.mesh();
  const Modelled again = extrude_faces(doc.mesh(), {5}, 0.05);
  doc.apply(again, {{3}});  // settles the delete's step, the move with it
  doc.settle_history();
  EXPECT_LT(doc.history_bytes(), mesh_bytes) << "every step settled: no mesh kept whole";

  // The states from the first to the last, and whether each step between two replaced the whole mesh
  // (the vertex edit did not).
  const std::vector<const CovarianceMesh*> states{&original, &extruded.mesh, &cut.mesh, &edited, &last, &again.mesh};
  const std::vector<bool> replaced{true, true, false, true, true};
  for (size_t i = replaced.size(); i-- > 0;) {
    ASSERT_EQ(doc.undo().has_value(), replaced[i]) << "undone to state " << i;
    expect_same_mesh(doc.mesh(), *states[i]);
  }
  for (size_t i = 0; i < replaced.size(); ++i) {
    ASSERT_EQ(doc.redo().has_value(), replaced[i]) << "redone to state " << i + 1;
    expect_same_mesh(doc.mesh(), *states[i + 1]);
    if (states[i + 1] == &last) EXPECT_TRUE(doc.dirty()) << "the move folded in after the save";
  }
}

// An undo in the time an operation's step waits swaps the meshes back: for operations that add,
// remove, merge and split vertices or keep them, the mesh and the vertices' origins are those an undo of the
// settled step gives, and so are the redo's; an undo past a step that waits for its redo settles it
// first; F9's discard keeps no mesh.
TEST(EditorDocument, AnUndoBeforeTheStepIsMadeSwapsTheMeshesExactly) {
  EditorDocument first;
  first.open_sample("sphere");
  const std::vector<std::function<Modelled(const CovarianceMesh&)>> operations{
      [](const CovarianceMesh& m) {
        return extrude_faces(m, {3, 4}, 0.1);
      },
      [](const CovarianceMesh& m) { return delete_vertices(m, {5}); },
      [](const CovarianceMesh& m) {
        return merge_vertices(m, {m.face(2)[0], m.face(2)[1]}, MergePoint::center);
      },
      [](const CovarianceMesh& m) {
        return split_faces(m, {1, 7});
      },
      [](const CovarianceMesh& m) { return loop_cut(m, m.face(0)[0], m.face(0)[1], 2); },
      [](const CovarianceMesh& m) {
        return transform_vertices(m, {0, 1, 2}, AffineMap::about(Vec3::Zero(), 1.5 * Mat3::Identity()));
      }};
  for (size_t k = 0; k < operations.size(); ++k) {
    SCOPED_TRACE("operation " + std::to_string(k));
    EditorDocument swapped, settled;
    swapped.open_sample("sphere");
    settled.open_sample("sphere");
    const CovarianceMesh before = swapped.mesh();
    const Modelled result = operations[k](before);
    swapped.apply(result, {{0}});
    settled.apply(result, {{0}});
    settled.settle_history();
    EXPECT_EQ(swapped.undo(), settled.undo());
    expect_same_mesh(swapped.mesh(), before);
    EXPECT_EQ(swapped.replaced_origin(), settled.replaced_origin());
    EXPECT_GT(swapped.history_bytes(), before.n_vertices() * sizeof(Vec3)) << "the mesh after is held";
    EXPECT_EQ(swapped.redo(), settled.redo());
    expect_same_mesh(swapped.mesh(), result.mesh);
    EXPECT_EQ(swapped.replaced_origin(), settled.replaced_origin());
    swapped.undo();
    swapped.settle_history();  // the step, undone, made while it waits for its redo
    EXPECT_LT(swapped.history_bytes(), before.n_vertices() * sizeof(Vec3));
    swapped.redo();
    expect_same_mesh(swapped.mesh(), result.mesh);
    EXPECT_EQ(swapped.replaced_origin(), settled.replaced_origin());
  }

  // Two operations; the second undone before it settles, then the first: the second's step is made
  // on the way, and both redo exactly.
  const Modelled extruded = extrude_faces(first.mesh(), {3}, 0.1);
  first.apply(extruded, {{0}});
  const Modelled deleted = delete_faces(first.mesh(), {1});
  first.apply(deleted, {{1}});
  ASSERT_TRUE(first.undo().has_value());
  expect_same_mesh(first.mesh(), extruded.mesh);
  ASSERT_TRUE(first.undo().has_value());
  EXPECT_FALSE(first.can_undo());
  EXPECT_LT(first.history_bytes(), deleted.mesh.n_vertices() * sizeof(Vec3)) << "no mesh kept whole";
  ASSERT_TRUE(first.redo().has_value());
  expect_same_mesh(first.mesh(), extruded.mesh);
  ASSERT_TRUE(first.redo().has_value());
  expect_same_mesh(first.mesh(), deleted.mesh);

  // An adjustment: the operation discarded and made again leaves one step, and nothing to redo.
  first.apply(extrude_faces(first.mesh(), {2}, 0.1), {{2}});
  first.discard_last_operation();
  expect_same_mesh(first.mesh(), deleted.mesh);
  EXPECT_FALSE(first.can_redo());
  const Modelled again = extrude_faces(first.mesh(), {2}, 0.2);
  first.apply(again, {{2}});
  first.settle_history();
  EXPECT_LT(first.history_bytes(), deleted.mesh.n_vertices() * sizeof(Vec3));
  first.undo();
  expect_same_mesh(first.mesh(), deleted.mesh);
}

// The mirror modifier's clipping: a vertex that starts an edit within the tolerance of the plane x = 0
// keeps x = 0 (its y and z move), one off it moves freely; without the clip both move.
TEST(EditorDocument, ClippingKeepsVerticesOnThePlane) {
  EditorDocument doc;
  doc.open_sample("cube");
  const Vec3 on_plane(1e-9, 1, 1);
  doc.begin_edit();
  doc.set_mean(6, on_plane);
  doc.commit_edit();
  doc.set_clip(PlaneClip{0, 1e-6});
  doc.begin_edit();
  doc.set_mean(6, on_plane + Vec3(0.5, 0.25, 0));
  doc.set_mean(0, doc.mesh().mean(0) + Vec3(0.5, 0, 0));
  doc.commit_edit();
  EXPECT_EQ(doc.mesh().mean(6), Vec3(0, 1.25, 1));
  EXPECT_EQ(doc.mesh().mean(0).x(), -0.5);
  doc.set_clip(std::nullopt);
  doc.begin_edit();
  doc.set_mean(6, Vec3(0.5, 1.25, 1));
  doc.commit_edit();
  EXPECT_EQ(doc.mesh().mean(6), Vec3(0.5, 1.25, 1));
}

}  // namespace
}  // namespace gps
