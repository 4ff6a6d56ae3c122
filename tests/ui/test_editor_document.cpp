#include "ui/editor_document.h"

#include <gtest/gtest.h>


#include "../support/temp_dir.h"
#include "core/error.h"
#include "core/mesh_io.h"
#include "core/text_file.h"
#include "core/samples.h"

namespace gps {
namespace {

TEST(EditorDocument, AMalformedFileKeepsTheCurrentMesh) {
  const test::TempDir dir;
  write_mesh(dir.file("good.ply"), make_sample("cube"));
  const std::string bad = dir.write("bad.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n1\n2\n");
  EditorDocument doc;
  doc.open(dir.file("good.ply"));
  const unsigned generation = doc.generation();
  doc.mesh.covariances[0] *= 2.0;
  VertexEdit e = EditHistory::begin(doc.mesh, {1});
  doc.mesh.covariances[1] *= 3.0;
  doc.history.commit(std::move(e), doc.mesh);
  try {
    doc.open(bad);
    FAIL() << "a malformed file opened";
  } catch (const Error& x) {
    EXPECT_NE(std::string(x.what()).find("bad.ply"), std::string::npos);
    EXPECT_EQ(std::string(x.what()).find('\n'), std::string::npos);
  }
  EXPECT_EQ(doc.generation(), generation);
  EXPECT_EQ(doc.mesh.n_vertices(), 8u);
  EXPECT_EQ(doc.mesh.covariance(1), 3.0 * make_sample("cube").covariance(1));
  EXPECT_TRUE(doc.dirty());
  EXPECT_EQ(doc.display_name(), "good.ply");
}

TEST(EditorDocument, SavingClearsDirtyAndKeepsTheFormat) {
  const test::TempDir dir;
  write_mesh(dir.file("b.ply"), make_sample("cube"), true);
  EditorDocument doc;
  doc.open(dir.file("b.ply"));
  EXPECT_TRUE(doc.can_save_in_place());
  VertexEdit e = EditHistory::begin(doc.mesh, {2});
  doc.mesh.covariances[2] *= 0.5;
  doc.history.commit(std::move(e), doc.mesh);
  EXPECT_TRUE(doc.dirty());
  doc.save(doc.ply_path());
  EXPECT_FALSE(doc.dirty());
  EXPECT_NE(read_text_file(dir.file("b.ply")).find("format binary_little_endian"), std::string::npos);
  EXPECT_EQ(read_mesh(dir.file("b.ply")).covariance(2), 0.5 * make_sample("cube").covariance(2));
  // Undo after saving is an unsaved change again; redo returns to the saved state.
  doc.history.undo(doc.mesh);
  EXPECT_TRUE(doc.dirty());
  doc.history.redo(doc.mesh);
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
}

TEST(EditorDocument, AFailedSaveKeepsTheFileAndTheState) {
  const test::TempDir dir;
  EditorDocument doc;
  doc.open_sample("cube");
  VertexEdit e = EditHistory::begin(doc.mesh, {0});
  doc.mesh.covariances[0] *= 2.0;
  doc.history.commit(std::move(e), doc.mesh);
  EXPECT_THROW(doc.save(dir.file("missing-folder/x.ply")), Error);
  EXPECT_TRUE(doc.dirty());
  EXPECT_FALSE(doc.can_save_in_place());
}

}  // namespace
}  // namespace gps
