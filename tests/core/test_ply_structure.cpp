// The structure of a PLY file (core/io/ply_io.h): its elements in any order, each vertex property,
// format line and vertex or face element once, nothing after the last record, and a surface to draw.
#include <gtest/gtest.h>

#include <functional>
#include <sstream>
#include <string>

#include "core/io/mesh_io.h"
#include "core/io/ply_io.h"
#include "core/io/polygon_soup.h"
#include "core/support/error.h"
#include "core/modelling/samples.h"
#include "tests/support/temp_dir.h"
#include "tests/support/error_of.h"

namespace gps {
namespace {

using test::error_of;

const std::string kVertexElement =
    "element vertex 3\nproperty double x\nproperty double y\nproperty double z\nproperty double cxx\n"
    "property double cxy\nproperty double cxz\nproperty double cyy\nproperty double cyz\nproperty double czz\n";
const std::string kFaceElement = "element face 1\nproperty list uchar int vertex_indices\n";
const std::string kVertices = "0 0 0 1 0 0 1 0 1\n1 0 0 2 0 0 1 0 1\n0 1 0 3 0 0 1 0 1\n";
const std::string kFace = "3 0 1 2\n";

std::string ascii_ply(const std::string& elements, const std::string& body) {
  return "ply\nformat ascii 1.0\n" + elements + "end_header\n" + body;
}

TEST(PlyStructure, FacesBeforeVerticesLoad) {
  const PlyContents ascii = parse_ply(ascii_ply(kFaceElement + kVertexElement, kFace + kVertices), "faces_first.ply");
  ASSERT_TRUE(ascii.has_covariances);
  EXPECT_EQ(ascii.mesh.n_vertices(), 3u);
  EXPECT_EQ(ascii.mesh.n_faces(), 1u);
  EXPECT_EQ(ascii.mesh.covariance(2)(0, 0), 3.0);
  // Binary: the face's list, then the vertices' doubles.
  std::string binary = "ply\nformat binary_little_endian 1.0\n" + kFaceElement + kVertexElement + "end_header\n";
  binary += '\x03';
  for (const int32_t i : {0, 1, 2}) binary.append(reinterpret_cast<const char*>(&i), 4);
  std::istringstream values(kVertices);
  for (double v; values >> v;) binary.append(reinterpret_cast<const char*>(&v), 8);
  const PlyContents b = parse_ply(binary, "faces_first_binary.ply");
  EXPECT_EQ(b.mesh.n_faces(), 1u);
  EXPECT_EQ(b.mesh.mean(1), ascii.mesh.mean(1));
  // The index bound is the vertex count the header declares.
  EXPECT_NE(error_of([&] {
              parse_ply(ascii_ply(kFaceElement + kVertexElement, "3 0 1 3\n" + kVertices), "out_of_range.ply");
            }).find("out_of_range.ply: line 16: face 0 refers to vertex 3, but there are 3 vertices"),
            std::string::npos);
}

TEST(PlyStructure, DataAfterTheLastRecordIsRefused) {
  const std::string elements = kVertexElement + kFaceElement;
  EXPECT_EQ(parse_ply(ascii_ply(elements, kVertices + kFace + "\n \t\r\n\n"), "blank.ply").mesh.n_faces(), 1u);
  // The header has 15 lines, the records 4: the garbage is on line 21, after one blank line.
  const std::string message =
      error_of([&] { parse_ply(ascii_ply(elements, kVertices + kFace + "\n  garbage 1 2\n"), "trailing.ply"); });
  EXPECT_EQ(message, "trailing.ply: line 21: 'garbage' after the last element's records");
  EXPECT_NE(error_of([&] {
              parse_ply(ascii_ply(elements, kVertices + kFace + "\x1b[2J"), "escape.ply");
            }).find("line 20: '\\x1B[2J' after the last element's records"),
            std::string::npos);
}

TEST(PlyStructure, DuplicatesInTheHeaderAreRefused) {
  const std::string twice =
      "element vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
      "property float x\n" +
      kFaceElement;
  EXPECT_EQ(error_of([&] { parse_ply(ascii_ply(twice, "0 0 0 5\n1 0 0 5\n0 1 0 5\n" + kFace), "twice.ply"); }),
            "twice.ply: line 7: property 'x' of element 'vertex' appears twice (the first is line 4)");
  EXPECT_EQ(error_of([&] {
              parse_ply("ply\nformat ascii 1.0\nformat binary_little_endian 1.0\n" + kVertexElement + kFaceElement +
                            "end_header\n" + kVertices + kFace,
                        "format.ply");
            }),
            "format.ply: line 3: a second format line (the first is line 2)");
  // A second face element is refused even where the first is empty.
  EXPECT_EQ(error_of([&] {
              parse_ply(
                  ascii_ply(kVertexElement + "element face 0\nproperty list uchar int vertex_indices\n" + kFaceElement,
                            kVertices + kFace),
                  "faces.ply");
            }),
            "faces.ply: line 15: a second face element (the first is line 13)");
}

// More face corners than a manifold mesh on the vertices has (3 vertices: 6) are refused where they
// pass that count and kCornersReadWhole, before the rest of the file is held (a later face out of
// range is not reached), as faces, as a triangle strip, and with the faces before the vertices. A
// smaller file is read whole, for the repair to mend.
TEST(PlyStructure, AFaceRepeatedIsRefusedWhereTheCornersPassAManifoldsCount) {
  const size_t passing = kCornersReadWhole / 3;  // the face whose corners pass the count
  std::string repeated;
  for (size_t f = 0; f <= passing; ++f) repeated += kFace;
  repeated += "3 0 1 7\n";
  const std::string faces =
      "element face " + std::to_string(passing + 2) + "\nproperty list uchar int vertex_indices\n";
  const std::string message =
      error_of([&] { parse_ply(ascii_ply(kVertexElement + faces, kVertices + repeated), "r.ply"); });
  EXPECT_NE(message.find("r.ply: face "), std::string::npos) << message;
  EXPECT_NE(message.find("non-manifold"), std::string::npos) << message;
  EXPECT_EQ(error_of([&] { parse_ply(ascii_ply(faces + kVertexElement, repeated + kVertices), "first.ply"); }),
            "first.ply: line " + std::to_string(16 + passing) + ": face " + std::to_string(passing) +
                " makes the mesh non-manifold (more face corners than 3 vertices can have)");
  const std::string strip = "element tristrips 2\nproperty list int int vertex_indices\n";
  std::string long_strip = std::to_string(passing + 3);
  for (size_t i = 0; i < passing + 3; ++i) long_strip += " " + std::to_string(i % 3);
  EXPECT_NE(error_of([&] {
              parse_ply(ascii_ply(kVertexElement + strip, kVertices + long_strip + "\n3 0 1 7\n"), "s.ply");
            }).find("non-manifold"),
            std::string::npos);
  const std::string few = "element face 5\nproperty list uchar int vertex_indices\n";
  EXPECT_EQ(error_of([&] {
              parse_ply(ascii_ply(kVertexElement + few, kVertices + kFace + kFace + kFace + kFace + "3 0 1 7\n"),
                        "f.ply");
            }),
            "f.ply: line 23: face 4 refers to vertex 7, but there are 3 vertices")
      << "read whole, to the face out of range";
}

// Gaussians without faces have no surface to draw: refused when read, as a plain mesh without faces is.
TEST(PlyStructure, ACovarianceMeshWithoutFacesIsRefused) {
  test::TempDir dir;
  const std::string points = dir.write("points.ply", ascii_ply(kVertexElement, kVertices));
  EXPECT_EQ(error_of([&] { read_mesh(points); }), points + ": the mesh has no faces");
  const std::string empty_faces =
      dir.write("empty_faces.ply",
                ascii_ply(kVertexElement + "element face 0\nproperty list uchar int vertex_indices\n", kVertices));
  EXPECT_EQ(error_of([&] { read_mesh(empty_faces); }), empty_faces + ": the mesh has no faces");
}

}  // namespace
}  // namespace gps
