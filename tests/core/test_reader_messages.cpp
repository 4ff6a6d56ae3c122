// What the readers put in their messages: bytes from the file escaped and long tokens cut
// (core/support/quoted_text.h), the path as given but on one line, and the true cause of a refusal.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <string>

#include "core/io/mesh_import.h"
#include "core/io/mesh_io.h"
#include "core/io/ply_io.h"
#include "core/support/error.h"
#include "tests/support/temp_dir.h"
#include "tests/support/error_of.h"

namespace gps {
namespace {

using test::error_of;

// A message that a terminal shows as one harmless line: no control byte, nothing that is not UTF-8.
void expect_one_harmless_line(const std::string& message, size_t max_size = 300) {
  for (const char c : message) {
    const unsigned char u = static_cast<unsigned char>(c);
    EXPECT_FALSE(u < 0x20 || u == 0x7f) << "byte " << int(u) << " in: " << message;
  }
  EXPECT_LE(message.size(), max_size) << message;
}

std::string ply_header() {
  return "ply\nformat ascii 1.0\n"
         "element vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
         "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
}

TEST(ReaderMessages, BytesFromTheFileAreEscapedAndLongTokensCut) {
  const std::string escape = "\x1b]0;owned\x07\x1b[2J";
  const std::string huge(10'000'000, '7');
  struct Case {
    std::string name, message, expected;
  };
  const std::vector<Case> cases = {
      {"escape.obj", error_of([&] { parse_obj("v 0 " + escape + " 0\n", "escape.obj"); }),
       "line 1: '\\x1B]0;owned\\x07\\x1B[2J' is not a number"},
      {"nul.obj", error_of([&] { parse_obj(std::string("v 0 1\0x 0\n", 11), "nul.obj"); }),
       "'1\\x00x' is not a number"},
      {"face.obj", error_of([&] { parse_obj("v 0 0 0\nf 1 2\xff 3\n", "face.obj"); }),
       "'2\\xFF' is not a vertex index"},
      {"huge.obj", error_of([&] { parse_obj("v 0 " + huge + "x 0\n", "huge.obj"); }),
       "line 1: '" + std::string(40, '7') + "…' is not a number"},
      {"count.off", error_of([&] { parse_off("OFF\n3\x1b 1 0\n", "count.off"); }),
       "line 2: '3\\x1B' is not a valid vertex count"},
      {"keyword.off", error_of([&] { parse_off("4\x9b\x32OFF\n", "keyword.off"); }), "'4\\x9B2OFF' (4D"},
      {"stl.stl", error_of([&] { parse_stl("solid x\nfacet\nvertex 0 \x1b 0\n", "stl.stl"); }), "'\\x1B' is not"},
      {"format.ply", error_of([&] { parse_ply("ply\nformat asc\x1bii 1.0\nend_header\n", "format.ply"); }),
       "line 2: unknown format 'asc\\x1Bii'"},
      {"line.ply", error_of([&] { parse_ply("ply\nformat ascii 1.0\nbogus \x1b[2J" + huge + "\n", "line.ply"); }),
       "line 3: unexpected header line 'bogus \\x1B[2J"},
      {"type.ply", error_of([&] {
         parse_ply("ply\nformat ascii 1.0\nelement v 1\nproperty fl\x07oat x\nend_header\n", "type.ply");
       }),
       "unknown property type 'fl\\x07oat'"},
      {"value.ply", error_of([&] { parse_ply(ply_header() + "0 0 \x1b\n1 0 0\n0 1 0\n3 0 1 2\n", "value.ply"); }),
       "'\\x1B' is not a number"},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(c.message.rfind(c.name + ": ", 0), 0u) << c.message;
    EXPECT_NE(c.message.find(c.expected), std::string::npos) << c.name << ": " << c.message;
    expect_one_harmless_line(c.message);
  }
}

TEST(ReaderMessages, APathWithControlBytesGivesOneLine) {
  test::TempDir dir;
  const std::string path = dir.write("two\nlines\x1b[1m.obj", "v 0 zero 0\n");
  const std::string message = error_of([&] { read_mesh(path); });
  EXPECT_NE(message.find("two\\x0Alines\\x1B[1m.obj: line 1: 'zero' is not a number"), std::string::npos) << message;
  expect_one_harmless_line(message, 1000);
  const std::string missing = error_of([&] { read_mesh(dir.file("gone\n.ply")); });
  EXPECT_NE(missing.find("gone\\x0A.ply: no such file"), std::string::npos) << missing;
  expect_one_harmless_line(missing, 1000);
  const std::string format = error_of([&] { read_mesh(dir.file("m.\x1b")); });
  EXPECT_NE(format.find("unknown mesh format '.\\x1B'"), std::string::npos) << format;
  expect_one_harmless_line(format, 1000);
}

// An OBJ file's messages number its vertices and faces from 1 with their lines, as its refusals by
// the repair's classes do, where the builder, the inference and the position check said "face 1" for
// the second face; OFF and PLY keep numbering from 0.
TEST(ReaderMessages, AnObjFilesElementsAreNumberedAsTheFileNumbersThem) {
  test::TempDir dir;
  // Face 2 (line 8) has three coincident corners: the inference refuses it.
  const std::string same =
      dir.write("same.obj", "v 0 0 0\nv 0 0 0\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 4 5 6\nf 1 2 3\n");
  const std::string degenerate = error_of([&] { read_mesh(same); });
  EXPECT_EQ(degenerate.rfind(dir.file("same.obj") + ": face 2 (line 8) is degenerate", 0), 0u) << degenerate;
  EXPECT_NE(degenerate.find("face 2 (line 8); --repair drops it"), std::string::npos) << degenerate;
  EXPECT_EQ(degenerate.find("face 1 "), std::string::npos) << degenerate;
  // Vertex 2 (line 3, after a comment) is out of range.
  const std::string big = dir.write("big.obj", "v 0 0 0\n# far\nv 1e200 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(error_of([&] { read_mesh(big); }),
            big + ": vertex 2 (line 3) has a coordinate 1e+200 beyond ±1e+100 (its products would overflow)");
  // Two triangles meeting at vertex 1 alone, without the file to find lines in: from 1 still.
  EXPECT_EQ(
      error_of([&] { parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\nf 1 2 3\nf 1 4 5\n", "bow.obj"); }),
      "bow.obj: vertex 1 is non-manifold (its faces do not form one fan)");
  // The same meshes as OFF: from 0.
  EXPECT_EQ(
      error_of([&] { parse_off("OFF\n5 2 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n3 0 1 2\n3 0 3 4\n", "bow.off"); }),
      "bow.off: vertex 0 is non-manifold (its faces do not form one fan)");
  const std::string off =
      dir.write("same.off", "OFF\n6 2 0\n0 0 0\n0 0 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 3 4 5\n3 0 1 2\n");
  const std::string off_message = error_of([&] { read_mesh(off); });
  EXPECT_EQ(off_message.rfind(off + ": face 1 is degenerate", 0), 0u) << off_message;
}

// A covariance that passes a Cholesky factorisation but whose smallest eigenvalue rounds below zero
// is named for what it is, not as an underflow.
TEST(ReaderMessages, ANegativeEigenvalueIsNotPositiveDefinite) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
      "property double cxx\nproperty double cxy\nproperty double cxz\nproperty double cyy\nproperty double cyz\n"
      "property double czz\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string message = error_of([&] {
    parse_ply(header +
                  "0 0 0 1 0 0 1 0 1\n1 0 0 1 0 0 1 0 1\n0 1 0 0.83555398099514466 -0.020419875885777317 "
                  "0.24856997571646414 0.062241460468005272 0.1745239336046274 0.60220455853685051\n3 0 1 2\n",
              "negative.ply");
  });
  EXPECT_NE(message.find("negative.ply: vertex 2 has a covariance that is not positive definite (eigenvalue -"),
            std::string::npos)
      << message;
  EXPECT_EQ(message.find("subnormal"), std::string::npos) << message;
  const std::string symmetric = error_of([&] {
    parse_ply(header + "0 0 0 1 0 0 1 0 1\n1 0 0 1 0 0 1 0 1\n0 1 0 1 2 0 1 0 1\n3 0 1 2\n", "indefinite.ply");
  });
  EXPECT_NE(symmetric.find("vertex 2 has a covariance that is not positive definite (eigenvalue -1)"),
            std::string::npos)
      << symmetric;
}

}  // namespace
}  // namespace gps
