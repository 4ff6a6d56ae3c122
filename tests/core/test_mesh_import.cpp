#include "core/io/mesh_import.h"
#include "core/io/polygon_soup.h"

#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Eigenvalues>
#include <cstring>
#include <functional>
#include <random>

#include "core/support/error.h"
#include "core/mesh/inference.h"
#include "core/io/mesh_io.h"
#include "tests/support/temp_dir.h"
#include "tests/support/error_of.h"

namespace gps {
namespace {

using test::error_of;

// The lines of OBJ elements named in messages, counted as the reader counts records: comments, blank
// lines, texture coordinates, normals and tags are no vertices or faces.
TEST(MeshImport, ObjLinesOfNamedElements) {
  const std::string text =
      "# a square\nv 0 0 0\n\nvt 0 0\nv 1 0 0\nvn 0 0 1\n  v 1 1 0\nv 0 1 0\nf 1 2 3\ng side\nt corner 1/1/0 0 2\n"
      "f 1 3 4\n";
  ElementNumbering numbering;
  find_obj_lines(text, {1, 3}, {1}, numbering);
  EXPECT_EQ(numbering.vertex_lines, (std::unordered_map<int, int>{{1, 5}, {3, 8}}));
  EXPECT_EQ(numbering.face_lines, (std::unordered_map<int, int>{{1, 12}}));
  numbering.base = 1;
  EXPECT_EQ(numbering.vertex(3), "vertex 4 (line 8)");
  EXPECT_EQ(numbering.vertex(2), "vertex 3") << "a line not looked up is not named";
  EXPECT_EQ(numbering.face(1), "face 2 (line 12)");
}

TEST(MeshImport, ObjWithSlashesAndNegativeIndices) {
  const auto m = parse_obj("# square\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1 -1/1\n", "a.obj");
  EXPECT_EQ(m.n_vertices(), 4u);
  EXPECT_EQ(m.n_faces(), 1u);
  EXPECT_EQ(m.face_size(0), 4);
  EXPECT_NE(error_of([] {
              parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", "b.obj");
            }).find("b.obj: line 4: vertex index 9 is out of range"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              parse_obj("v 0 0 0\nv 1 0 0\nf 1 2\n", "c.obj");
            }).find("line 3: a face needs at least 3 vertices"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              parse_obj("v 0 nan 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "d.obj");
            }).find("d.obj: vertex 1 (line 1) has a position that is not finite"),
            std::string::npos);
  EXPECT_NE(error_of([] { parse_obj("", "e.obj"); }).find("e.obj: the file is empty"), std::string::npos);
}

// After a vertex's coordinates only numbers (a weight, a colour) or a comment may follow: a stray
// word is refused naming the line, not ignored.
TEST(MeshImport, ObjVertexTrailingWordsAreNumbersOrRefused) {
  const auto m = parse_obj("v 0 0 0 1\nv 1 0 0 0.5 0.5 0.5\nv 0 1 0 # apex\nf 1 2 3\n", "a.obj");
  EXPECT_EQ(m.n_vertices(), 3u);
  EXPECT_EQ(m.mean(1), Vec3(1, 0, 0));
  EXPECT_EQ(error_of([] { parse_obj("v 0 0 0\nv 1 0 0 xyz\nv 0 1 0\nf 1 2 3\n", "b.obj"); }),
            "b.obj: line 2: 'xyz' is not a number (after the vertex's coordinates: a weight or a colour)");
}

TEST(MeshImport, OffWithCommentsAndColours) {
  const auto m = parse_off(
      "OFF\n# tetrahedron\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1 255 0 0\n3 0 1 3\n3 1 2 3\n3 0 3 2\n", "t.off");
  EXPECT_EQ(m.n_vertices(), 4u);
  EXPECT_EQ(m.n_faces(), 4u);
  EXPECT_NE(
      error_of([] { parse_off("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n", "x.off"); }).find("refers to vertex 5"),
      std::string::npos);
  EXPECT_NE(error_of([] { parse_off("OFF\n3 1 0\n0 0 0\n1 0 0\n", "y.off"); }).find("truncated"), std::string::npos);
  EXPECT_EQ(error_of([] { parse_off("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n", "z.off"); }),
            "z.off: line 7: '3' after the 1 face the header counts (it counts fewer than the file holds?)");
}

// An OFF face repeated is refused where the corners pass what a manifold mesh on the vertices has
// (3 vertices: 6), before the rest is held: a later face out of range is not reached.
TEST(MeshImport, OffFaceRepeatedIsRefusedWhereTheCornersPassAManifoldsCount) {
  const size_t passing = kCornersReadWhole / 3;  // the face whose corners pass the count (a smaller file is read whole)
  std::string off = "OFF\n3 " + std::to_string(passing + 2) + " 0\n0 0 0\n1 0 0\n0 1 0\n";
  for (size_t f = 0; f <= passing; ++f) off += "3 0 1 2\n";
  const std::string message = error_of([&] { parse_off(off + "3 0 1 7\n", "r.off"); });
  EXPECT_NE(message.find("r.off: face "), std::string::npos) << message;
  EXPECT_NE(message.find("non-manifold"), std::string::npos) << message;
}

// COFF/NOFF carry colours or normals after each vertex position: they are skipped.
TEST(MeshImport, OffVariantsWithPerVertexValues) {
  const auto m = parse_off(
      "COFF\n4 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n1 1 0 0 0 255 255\n0 1 0 9 9 9 9\n4 0 1 2 3\n", "c.off");
  EXPECT_EQ(m.n_vertices(), 4u);
  EXPECT_EQ(m.n_faces(), 1u);
  EXPECT_EQ(m.mean(2), Vec3(1, 1, 0));
  EXPECT_NE(error_of([] {
              parse_off("4OFF\n3 1 0\n0 0 0 1\n1 0 0 1\n0 1 0 1\n3 0 1 2\n", "d.off");
            }).find("d.off: line 1: '4OFF'"),
            std::string::npos);
  EXPECT_NE(
      error_of([] { parse_off("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "e.off"); }).find("face 0 has fewer than 3"),
      std::string::npos);
}

// write_mesh(.obj) then read_mesh: positions exact (17 significant digits), faces in order.
TEST(MeshImport, ObjRoundTripKeepsPositionsExactly) {
  test::TempDir dir;
  CovarianceMesh m = make_covariance_mesh({{0.1, 1.0 / 3, -2e-7}, {1, 0, 0}, {1, 1, 0}, {0, 1, 1e30}},
                                          std::vector<Mat3>(4, Mat3::Identity()), {{0, 1, 2, 3}}, "q");
  write_mesh(dir.file("q.obj"), m);
  ImportOptions isotropic;
  isotropic.covariance = ImportOptions::Covariance::isotropic;
  const CovarianceMesh r = read_mesh(dir.file("q.obj"), isotropic);
  ASSERT_EQ(r.n_vertices(), 4u);
  for (size_t i = 0; i < 4; ++i) EXPECT_EQ(r.mean(i), m.mean(i));
  const std::vector<int> face(r.face(0).begin(), r.face(0).end());
  EXPECT_EQ(face, (std::vector<int>{0, 1, 2, 3}));
}

// A binary STL whose header starts with "solid" and mentions "facet" is still read as binary.
TEST(MeshImport, BinaryStlWithSolidHeader) {
  std::string binary = "solid exported by a tool that writes facet in the header";
  binary.resize(80, ' ');
  const uint32_t n = 1;
  binary.append(reinterpret_cast<const char*>(&n), 4);
  const float tri[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0};
  binary.append(reinterpret_cast<const char*>(tri), sizeof tri);
  binary.append(2, '\0');
  const auto m = parse_stl(binary, "s.stl");
  EXPECT_EQ(m.n_vertices(), 3u);
  EXPECT_EQ(m.n_faces(), 1u);
}

TEST(MeshImport, StlWithNonFiniteCornerIsAnError) {
  std::string binary(84, '\0');
  const uint32_t n = 1;
  std::memcpy(&binary[80], &n, 4);
  const float tri[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, std::nanf(""), 1, 0};
  binary.append(reinterpret_cast<const char*>(tri), sizeof tri);
  binary.append(2, '\0');
  EXPECT_NE(error_of([&] { parse_stl(binary, "n.stl"); }).find("n.stl: triangle 0 has a corner that is not finite"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              parse_stl("solid x\nfacet normal 0 0 1\nvertex 0 0 0\nvertex 1 0 0\nendsolid\n", "t.stl");
            }).find("t.stl: a facet does not have three vertices"),
            std::string::npos);
}

TEST(MeshImport, StlAsciiAndBinaryWeldCorners) {
  const std::string ascii =
      "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
      "facet normal 0 0 1\nouter loop\nvertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n";
  const auto a = parse_stl(ascii, "a.stl");
  EXPECT_EQ(a.n_vertices(), 4u);
  EXPECT_EQ(a.n_faces(), 2u);
  std::string binary(80, ' ');
  const uint32_t n = 2;
  binary.append(reinterpret_cast<const char*>(&n), 4);
  const float tris[2][12] = {{0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 0}};
  for (const auto& t : tris) {
    binary.append(reinterpret_cast<const char*>(t), 48);
    binary.append(2, '\0');
  }
  const auto b = parse_stl(binary, "b.stl");
  EXPECT_EQ(b.n_vertices(), 4u);
  EXPECT_EQ(b.n_faces(), 2u);
  EXPECT_NE(error_of([&] { parse_stl(binary.substr(0, 120), "c.stl"); }).find("truncated"), std::string::npos);
}

TEST(MeshImport, ReadMeshInfersCovariancesForPlainFiles) {
  test::TempDir dir;
  const std::string path = dir.write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  const CovarianceMesh inferred = read_mesh(path);
  ImportOptions iso;
  iso.covariance = ImportOptions::Covariance::isotropic;
  const CovarianceMesh isotropic = read_mesh(path, iso);
  EXPECT_TRUE(isotropic.covariance(0).isApprox(0.25 * Mat3::Identity()));
  EXPECT_FALSE(inferred.covariance(0).isApprox(isotropic.covariance(0)));
}

// A planar mesh: the smallest axis of every inferred covariance is the plane's normal (Eq. 16–17).
TEST(Inference, PlanarMeshGivesFlatCovariancesAlongTheNormal) {
  test::TempDir dir;
  CovarianceMesh m = read_mesh(dir.write("g.obj",
                                         "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1.2 0\n"
                                         "f 1 2 5 4\nf 2 3 6 5\n"));
  for (double bias : {0.01, 0.05, 0.2}) {
    infer_covariances(m, bias);
    for (const Mat3& c : m.covariances) {
      const Eigen::SelfAdjointEigenSolver<Mat3> eig(c);
      EXPECT_NEAR(std::abs(eig.eigenvectors().col(0).z()), 1.0, 1e-9);
      // A smaller bias flattens more: the ratio of smallest to largest σ² is about the bias.
      EXPECT_LT(eig.eigenvalues()(0) / eig.eigenvalues()(2), 2.0 * bias);
    }
  }
  EXPECT_THROW(infer_covariances(m, 0.0), Error);
}

// Truncations and single-byte corruptions of OBJ, OFF and STL either read or give a one-line gps::Error.
TEST(MeshImport, CorruptedFilesNeverCrash) {
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nf 1 2 3 4\nf 1 5 2\nf -1 -4 -3\n";
  const std::string off = "OFF\n5 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n4 0 1 2 3\n3 0 4 1\n3 4 0 3\n";
  std::string stl(80, ' ');
  const uint32_t n = 2;
  stl.append(reinterpret_cast<const char*>(&n), 4);
  const float tris[2][12] = {{0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 0}};
  for (const auto& t : tris) stl.append(reinterpret_cast<const char*>(t), sizeof t).append(2, '\0');
  std::mt19937 rng(3);
  const auto survives = [](const std::function<void()>& f) {
    try {
      f();
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    }
  };
  for (int trial = 0; trial < 3000; ++trial) {
    std::string a = obj, b = off, c = stl;
    a[rng() % a.size()] = "0123456789 -/.fv\n"[rng() % 17];
    b[rng() % b.size()] = "0123456789 -.#\n"[rng() % 15];
    c[84 + rng() % (c.size() - 84)] = char(rng());
    survives([&] { parse_obj(a, "a.obj"); });
    survives([&] { parse_off(b, "b.off"); });
    survives([&] { parse_stl(c, "c.stl"); });
    survives([&] { parse_obj(obj.substr(0, rng() % obj.size()), "a.obj"); });
    survives([&] { parse_off(off.substr(0, rng() % off.size()), "b.off"); });
    survives([&] { parse_stl(stl.substr(0, rng() % stl.size()), "c.stl"); });
  }
}

}  // namespace
}  // namespace gps

namespace gps {
namespace {

TEST(MeshImport, AByteOrderMarkAndExportersSpellingsAreRead) {
  test::TempDir dir;
  // With a UTF-8 byte order mark the first line was the mark's and not a vertex's: every index moved.
  const CovarianceMesh obj =
      read_mesh(dir.write("b.obj", "\xEF\xBB\xBFv 9 9 9\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n"));
  ASSERT_EQ(obj.n_vertices(), 4u);
  EXPECT_EQ(obj.mean(0), Vec3(9, 9, 9));
  ElementNumbering numbering;  // the lines that messages name count the same way
  find_obj_lines("\xEF\xBB\xBFv 9 9 9\nv 0 0 0\n", {1}, {}, numbering);
  EXPECT_EQ(numbering.vertex_lines, (std::unordered_map<int, int>{{1, 2}}));
  // Lines ended by "\r\n" or by a lone '\r' (old Mac files) as by '\n'; that one was refused at its line 1.
  const std::string square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
  for (const std::string end : {"\r\n", "\r"}) {
    std::string text = square;
    for (size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at + end.size()))
      text.replace(at, 1, end);
    const CovarianceMesh m = read_mesh(dir.write("ends.obj", text));
    EXPECT_EQ(m.n_vertices(), 4u);
    EXPECT_EQ(m.n_faces(), 1u);
    ElementNumbering lines;
    find_obj_lines(text, {3}, {0}, lines);
    EXPECT_EQ(lines.vertex_lines, (std::unordered_map<int, int>{{3, 4}}));
    EXPECT_EQ(lines.face_lines, (std::unordered_map<int, int>{{0, 5}}));
  }
  const CovarianceMesh ply =
      read_mesh(dir.write("b.ply",
                          "\xEF\xBB\xBFply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                          "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                          "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
  EXPECT_EQ(ply.n_faces(), 1u);
  // An ASCII STL in capitals, after the mark and spaces.
  const std::string facet =
      "FACET NORMAL 0 0 1\n OUTER LOOP\n  VERTEX 0 0 0\n  VERTEX 1 0 0\n  VERTEX 0 1 0\n"
      " ENDLOOP\nENDFACET\n";
  EXPECT_EQ(read_mesh(dir.write("b.stl", "\xEF\xBB\xBF  SOLID x\n" + facet + "ENDSOLID x\n")).n_faces(), 1u);
}

// A line ending in a backslash goes on in the next (the OBJ format's line continuation, which
// exporters use for long faces); it was refused with a message that did not say why. Messages name
// a continued line by its first line.
TEST(MeshImport, ObjLinesContinuedByABackslashAreJoined) {
  test::TempDir dir;
  const std::string text = "v 0 0 \\\n  0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 \\\r\n 3 \\ \n4\nv 7 7 7\n";
  const CovarianceMesh m = read_mesh(dir.write("c.obj", text));
  ASSERT_EQ(m.n_vertices(), 5u);
  ASSERT_EQ(m.n_faces(), 1u);
  EXPECT_EQ(m.face_size(0), 4);
  EXPECT_EQ(m.mean(0), Vec3(0, 0, 0));
  EXPECT_EQ(m.mean(4), Vec3(7, 7, 7));
  ElementNumbering lines;
  find_obj_lines(text, {1, 4}, {0}, lines);
  EXPECT_EQ(lines.vertex_lines, (std::unordered_map<int, int>{{1, 3}, {4, 9}}));
  EXPECT_EQ(lines.face_lines, (std::unordered_map<int, int>{{0, 6}}));
  try {
    read_mesh(dir.write("bad.obj", "v 0 0 0\nv 1 \\\n0 x\n"));
    FAIL() << "read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("line 2: "), std::string::npos) << e.what();
  }
  // A backslash on the last line continues nothing: the line as it stands.
  EXPECT_THROW(read_mesh(dir.write("end.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 \\")), Error);
}

TEST(MeshImport, AsciiStlFacetsOfOtherThanThreeVerticesAndTruncationAreRefused) {
  const std::string facet =
      "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n"
      " endloop\nendfacet\n";
  // A facet of 4 and one of 2 made two triangles across them.
  const std::string four_two =
      "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
      "vertex 1 1 0\nendloop\nendfacet\nfacet normal 0 0 1\nouter loop\nvertex 0 0 1\n"
      "vertex 1 0 1\nendloop\nendfacet\nendsolid x\n";
  EXPECT_EQ(error_of([&] { parse_stl(four_two, "f.stl"); }),
            "f.stl: line 2: a facet with 4 vertices (an STL facet has 3)");
  EXPECT_EQ(error_of([&] { parse_stl("solid x\n" + facet, "t.stl"); }),
            "t.stl: the file ends before its 'endsolid' (truncated)");
  EXPECT_EQ(error_of([&] { parse_stl("solid x\nendsolid x\n", "e.stl"); }), "e.stl: no triangles");
  EXPECT_EQ(parse_stl("solid x\n" + facet + "endsolid x\n", "a.stl").n_faces(), 1u);
}

}  // namespace
}  // namespace gps
