#include "core/io/ply_io.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <random>

#include "core/support/error.h"
#include "core/io/mesh_io.h"
#include "core/modelling/samples.h"
#include "tests/support/random_spd.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

CovarianceMesh mesh_with_random_covariances() {
  CovarianceMesh m = make_sample("cylinder");
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-1, 1);
  for (auto& c : m.covariances) c = test::random_spd(rng, 9e-3) / 9.0;  // a/3 · (a/3)ᵀ + 10⁻³ I
  for (size_t i = 0; i < m.n_vertices(); ++i) m.set_mean(i, m.mean(i) + Vec3(u(rng), u(rng), u(rng)) * 1e-3);
  return m;
}

void expect_identical(const CovarianceMesh& a, const CovarianceMesh& b) {
  ASSERT_EQ(a.n_vertices(), b.n_vertices());
  ASSERT_EQ(a.n_faces(), b.n_faces());
  for (size_t i = 0; i < a.n_vertices(); ++i) {
    EXPECT_EQ(a.mean(i), b.mean(i));
    EXPECT_EQ(a.covariance(i), b.covariance(i));
  }
  for (size_t f = 0; f < a.n_faces(); ++f) {
    const std::span<const int> fa = a.face(f), fb = b.face(f);
    EXPECT_EQ(std::vector<int>(fa.begin(), fa.end()), std::vector<int>(fb.begin(), fb.end()));
  }
}

TEST(PlyIo, RoundTripIsExactInAsciiAndBinary) {
  test::TempDir dir;
  const CovarianceMesh m = mesh_with_random_covariances();
  for (const bool binary : {false, true}) {
    const std::string path = dir.file(binary ? "b.ply" : "a.ply");
    write_mesh(path, m, binary);
    expect_identical(m, read_mesh(path));
  }
}

// A Σ symmetric only within rounding (as Python or an edit may hand one over) is saved as its check read
// it, its lower triangle: the upper one's tiny xz would make a Σ whose smallest eigenvalue, 1e-38 of
// its largest, the check no longer tells from zero, and the file would not load.
TEST(PlyIo, ANearlySymmetricCovarianceIsSavedAsItWasAccepted) {
  test::TempDir dir;
  CovarianceMesh m = make_sample("cube");
  Mat3 sigma = Vec3(1.0, 1.1754943508222875e-38, 1.0).asDiagonal();
  sigma(0, 2) = 8.8e-44;
  m.set_covariance(5, sigma);
  validate_gaussians(m, "cube");
  for (const bool binary : {false, true}) {
    const std::string path = dir.file(binary ? "b.ply" : "a.ply");
    write_mesh(path, m, binary);
    const CovarianceMesh read = read_mesh(path);
    EXPECT_EQ(read.covariance(5), Mat3(sigma.selfadjointView<Eigen::Lower>()));
  }
}

TEST(PlyIo, ReadsFloatsAnyPropertyOrderAndExtraElements) {
  const std::string ply =
      "ply\nformat ascii 1.0\ncomment made by hand\nelement vertex 3\nproperty float cyy\nproperty float x\n"
      "property float y\nproperty uchar red\nproperty float z\nproperty float cxx\nproperty float cxy\n"
      "property float cxz\nproperty float cyz\nproperty float czz\nelement face 1\n"
      "property list uchar int vertex_indices\nelement edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n"
      "2 0 0 255 0 1 0 0 0 3\n2 1 0 0 0 1 0 0 0 3\n2 0 1 0 0 1 0 0 0 3\n3 0 1 2\n0 1\n";
  const PlyContents c = parse_ply(ply, "hand.ply");
  ASSERT_TRUE(c.has_covariances);
  EXPECT_EQ(c.mesh.n_vertices(), 3u);
  EXPECT_EQ(c.mesh.covariance(1), Vec3(1, 2, 3).asDiagonal().toDenseMatrix());
  EXPECT_EQ(c.mesh.mean(1), Vec3(1, 0, 0));
}

TEST(PlyIo, ReadsTriangleStripsWithRestarts) {
  // A 4×3 grid of vertices: one strip along each row of squares, separated by a restart, and a
  // strip of one degenerate triangle (a repeated index), left out.
  std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 12\nproperty float x\nproperty float y\nproperty float z\n"
      "element tristrips 1\nproperty list int int vertex_indices\nend_header\n";
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) ply += std::to_string(x) + " " + std::to_string(y) + " 0\n";
  ply += "21 0 4 1 5 2 6 3 7 -1 4 8 5 9 6 10 7 11 -1 1 1 2\n";
  const CovarianceMesh m = parse_ply(ply, "strips.ply").mesh;
  EXPECT_EQ(m.n_vertices(), 12u);
  ASSERT_EQ(m.n_faces(), 6u + 6u);
  // One orientation throughout: every triangle faces +z (or every one −z).
  int up = 0;
  for (size_t f = 0; f < m.n_faces(); ++f) {
    std::vector<Vec3> p;
    for (const int v : m.face(f)) p.push_back(m.mean(size_t(v)));
    up += (p[1] - p[0]).cross(p[2] - p[0]).z() > 0 ? 1 : -1;
  }
  EXPECT_EQ(std::abs(up), 12);
  const std::string bad =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement tristrips 1\nproperty list int int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n4 0 1 2 7\n";
  try {
    parse_ply(bad, "bad.ply");
    FAIL() << "an index past the vertices was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("strip 0 refers to vertex 7, but there are 3 vertices"), std::string::npos)
        << e.what();
  }
}

TEST(PlyIo, PlainPlyGetsInferredCovariances) {
  test::TempDir dir;
  const std::string path = dir.write("plain.ply",
                                     "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
                                     "property double z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                     "end_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
  const CovarianceMesh m = read_mesh(path);
  EXPECT_TRUE(is_spd(m.covariance(0)));
  EXPECT_NE(m.covariance(0), Mat3::Identity());
}

// Each malformed file: the message names the file and the problem.
struct BadInput {
  const char* name;
  std::string contents;
  const char* expected;
};

std::string header(const std::string& body_format, int nv, int nf) {
  return "ply\nformat " + body_format + " 1.0\nelement vertex " + std::to_string(nv) +
         "\nproperty double x\nproperty double y\nproperty double z\nproperty double cxx\nproperty double cxy\n"
         "property double cxz\nproperty double cyy\nproperty double cyz\nproperty double czz\nelement face " +
         std::to_string(nf) + "\nproperty list uchar int vertex_indices\nend_header\n";
}

std::string binary_vertices(int n) {
  std::string out;
  for (int i = 0; i < n; ++i) {
    const double v[9] = {double(i % 2), double(i / 2), 0, 1, 0, 0, 1, 0, 1};
    out.append(reinterpret_cast<const char*>(v), sizeof v);
  }
  return out;
}

TEST(PlyIo, MalformedFilesGiveOneLineErrors) {
  const std::string v0 = "0 0 0 1 0 0 1 0 1\n", v1 = "1 0 0 1 0 0 1 0 1\n", tri = v0 + v1 + "0 1 0 1 0 0 1 0 1\n";
  const std::vector<BadInput> cases = {
      {"empty.ply", "", "empty"},
      {"header.ply", "plx\n", "not a PLY file"},
      {"format.ply", "ply\nformat binary_middle_endian 1.0\nend_header\n", "unknown format"},
      {"noend.ply", "ply\nformat ascii 1.0\nelement vertex 1\n", "end_header"},
      {"proptype.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n",
       "unknown property type"},
      {"index.ply", header("ascii", 3, 1) + tri + "3 0 1 7\n", "refers to vertex 7"},
      {"small_face.ply", header("ascii", 3, 1) + tri + "2 0 1\n", "face 0 has 2 vertices"},
      {"nan.ply", header("ascii", 3, 1) + "0 nan 0 1 0 0 1 0 1\n" + tri.substr(tri.find('\n') + 1) + "3 0 1 2\n",
       "vertex 0 has a position that is not finite"},
      {"inf.ply", header("ascii", 3, 1) + v0 + v1 + "0 1 0 inf 0 0 1 0 1\n3 0 1 2\n",
       "vertex 2 has a covariance that is not finite"},
      {"spd.ply", header("ascii", 3, 1) + v0 + v1 + "0 1 0 1 2 0 1 0 1\n3 0 1 2\n",
       "vertex 2 has a covariance that is not positive definite (eigenvalue -1)"},
      {"underflow.ply", header("ascii", 3, 1) + "0 1e-400 0 1 0 0 1 0 1\n" + v1 + v1 + "3 0 1 2\n",
       "line 16: '1e-400' underflows"},
      {"overflow.ply", header("ascii", 3, 1) + "0 -1e400 0 1 0 0 1 0 1\n" + v1 + v1 + "3 0 1 2\n",
       "'-1e400' overflows"},
      {"subnormal.ply", header("ascii", 3, 1) + v0 + v1 + "0 1 0 1e-310 0 0 1e-310 0 1e-310\n3 0 1 2\n",
       "vertex 2 has a covariance eigenvalue 1e-310 below 1e-100 (subnormal: underflows)"},
      {"tiny.ply", header("ascii", 3, 1) + v0 + "1 0 0 1e-200 0 0 1 0 1\n" + v1 + "3 0 1 2\n",
       "vertex 1 has a covariance eigenvalue 1e-200 below 1e-100"},
      {"hugecov.ply", header("ascii", 3, 1) + v0 + v1 + "0 1 0 1e308 0 0 1e308 0 1e308\n3 0 1 2\n",
       "vertex 2 has a covariance eigenvalue 1e+308 above 1e+100"},
      {"far.ply", header("ascii", 3, 1) + v0 + "1e308 0 0 1 0 0 1 0 1\n-1e308 1 0 1 0 0 1 0 1\n3 0 1 2\n",
       "vertex 1 has a coordinate 1e+308 beyond"},
      {"word.ply", header("ascii", 3, 1) + "0 zero 0 1 0 0 1 0 1\n" + v1 + v1 + "3 0 1 2\n",
       "line 16: 'zero' is not a number"},
      {"short_ascii.ply", header("ascii", 3, 1) + tri, "truncated"},
      {"long_line.ply", header("ascii", 3, 1) + v0 + v1 + "0 1 0 1 0 0 1 0 1 7\n3 0 1 2\n", "line 18: more values"},
      {"truncated.ply", header("binary_little_endian", 4, 1) + binary_vertices(4).substr(0, 200), "truncated"},
      {"truncated_faces.ply",
       header("binary_little_endian", 3, 1) + binary_vertices(3) + std::string("\x03\x00\x00", 3), "truncated"},
      {"huge.ply", header("binary_little_endian", 2000000000, 1) + binary_vertices(3), "more than the file holds"},
      // A second face the header does not count was dropped without a word.
      {"short_count.ply",
       header("binary_little_endian", 3, 1) + binary_vertices(3) + std::string("\x03\0\0\0\0\x01\0\0\0\x02\0\0\0", 13) +
           std::string("\x03\0\0\0\0\x02\0\0\0\x01\0\0\0", 13),
       "13 bytes after the last element's records (the header counts fewer records than the file holds?)"},
      {"nonmanifold.ply",
       header("ascii", 5, 3) + tri + "0 -1 0 1 0 0 1 0 1\n0 0 1 1 0 0 1 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n",
       "non-manifold"},
  };
  test::TempDir dir;
  for (const auto& c : cases) {
    const std::string path = dir.write(c.name, c.contents);
    try {
      read_mesh(path);
      ADD_FAILURE() << c.name << " was accepted";
    } catch (const Error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(path), std::string::npos) << what;
      EXPECT_NE(what.find(c.expected), std::string::npos) << c.name << ": " << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
      EXPECT_EQ(e.exit_code(), 1);
    }
  }
  EXPECT_THROW(read_mesh(dir.file("missing.ply")), Error);
  EXPECT_THROW(read_mesh(dir.path().string() + "/"), Error);
  std::filesystem::create_directory(dir.file("folder.ply"));
  try {
    read_mesh(dir.file("folder.ply"));
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos);
  }
  EXPECT_THROW(read_mesh(dir.write("mesh.xyz", "1 2 3\n")), Error);
}

TEST(PlyIo, FailedWriteLeavesTheTargetAndNoTemporaryFile) {
  test::TempDir dir;
  const CovarianceMesh m = make_sample("cube");
  const std::string target = dir.write("keep.ply", "old contents");
  EXPECT_THROW(write_mesh(dir.file("no/such/folder/x.ply"), m), Error);
  EXPECT_THROW(write_mesh(dir.file("x.stl"), m), Error);
  EXPECT_THROW(write_mesh(dir.path().string(), m), Error);
  size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path())) ++files;
  EXPECT_EQ(files, 1u);
  write_mesh(target, m);
  EXPECT_EQ(read_mesh(target).n_vertices(), 8u);
}

// Values the readers would refuse are not written either: no file gpsurf cannot read back.
TEST(PlyIo, WritingRefusesWhatReadingWouldRefuse) {
  test::TempDir dir;
  CovarianceMesh m = make_sample("cone");
  m.covariances[3] = Mat3::Identity() * 1e-310;
  try {
    write_mesh(dir.file("m.ply"), m, true);
    ADD_FAILURE() << "written";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("m.ply: not written: vertex 3 has a covariance eigenvalue"), std::string::npos)
        << e.what();
  }
  m.covariances[3] = Mat3::Identity();
  m.set_mean(5, Vec3(0, std::nan(""), 0));
  EXPECT_THROW(write_mesh(dir.file("m.obj"), m, false), Error);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

// Distinct vertices at ±1e308 (an OBJ): refused for the range, not reported as a degenerate face.
TEST(PlyIo, HugePositionsInImportsAreNamedAsSuch) {
  test::TempDir dir;
  const std::string path = dir.write("far.obj", "v 1e308 0 0\nv -1e308 0 0\nv 0 1e308 0\nf 1 2 3\n");
  try {
    read_mesh(path);
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("far.obj: vertex 1 (line 1) has a coordinate 1e+308 beyond"), std::string::npos)
        << e.what();
  }
}

TEST(PlyIo, CorruptListLengthsAndIndicesAreErrors) {
  const std::string v0 = "0 0 0 1 0 0 1 0 1\n", v1 = "1 0 0 1 0 0 1 0 1\n", v2 = "0 1 0 1 0 0 1 0 1\n";
  const std::string h = header("ascii", 3, 1) + v0 + v1 + v2;
  const std::vector<BadInput> cases = {
      {"nan_count.ply", h + "nan 0 1 2\n", "line 19: face 0: list length nan is not a count"},
      {"frac_count.ply", h + "3.5 0 1 2\n", "list length 3.5 is not a count"},
      {"neg_count.ply", h + "-3 0 1 2\n", "list length -3 is not a count"},
      {"long_count.ply", h + "4 0 1 2\n", "line 19: face 0: list length 4 exceeds the values on the line"},
      {"huge_count.ply", h + "1e300 0 1 2\n",
       "list length 1e+300 is more than its count type holds (a non-negative integer of 8 bits)"},
      {"big_count.ply", h + "4000000000 0 1 2\n", "list length 4000000000 is more than its count type holds"},
      {"nan_index.ply", h + "3 0 1 nan\n", "face 0 refers to vertex nan"},
      {"frac_index.ply", h + "3 0 1 1.5\n", "face 0 refers to vertex 1.5, which is not a whole number"},
      {"neg_index.ply", h + "3 0 -1 2\n", "face 0 refers to vertex -1"},
      {"two_vertex.ply",
       "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
       "element vertex 0\nproperty float x\nproperty float y\nproperty float z\nend_header\n",
       "line 7: a second vertex element"},
      {"no_xyz.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n",
       "lacks x, y or z"},
      {"some_cov.ply",
       "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
       "property float cxx\nend_header\n0 0 0 1\n",
       "only some of"},
      {"no_format.ply", "ply\nelement vertex 0\nend_header\n", "no format line"},
      {"huge_binary_list.ply",
       header("binary_little_endian", 3, 1) + binary_vertices(3) + std::string("\xff\x00\x00\x00\x00", 5),
       "face 0: list length 255 exceeds the data left (truncated)"},
  };
  for (const auto& c : cases) {
    try {
      parse_ply(c.contents, c.name);
      ADD_FAILURE() << c.name << " was accepted";
    } catch (const Error& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(std::string(c.name) + ": ", 0), 0u) << what;
      EXPECT_NE(what.find(c.expected), std::string::npos) << c.name << ": " << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
}

// An element without properties has empty binary records: a huge count costs nothing.
TEST(PlyIo, HugeElementWithoutPropertiesIsSkippedAtOnce) {
  std::string ply = header("binary_little_endian", 3, 1);
  ply.insert(ply.find("end_header"), "element nothing 1000000000000000\n");
  ply += binary_vertices(3) + std::string("\x03", 1);
  for (const int32_t i : {0, 1, 2}) ply.append(reinterpret_cast<const char*>(&i), 4);
  const PlyContents c = parse_ply(ply, "empty_records.ply");
  EXPECT_EQ(c.mesh.n_faces(), 1u);
}

// Faces with more than 255 corners do not fit the usual uchar list length: the writer widens it.
TEST(PlyIo, RoundTripOfAFaceWithMoreThan255Corners) {
  std::vector<Vec3> p;
  std::vector<int> face;
  for (int i = 0; i < 300; ++i) {
    p.emplace_back(std::cos(i * 0.021), std::sin(i * 0.021), 0);
    face.push_back(i);
  }
  const CovarianceMesh m =
      make_covariance_mesh(p, std::vector<Mat3>(p.size(), 0.01 * Mat3::Identity()), {face}, "ngon");
  test::TempDir dir;
  for (const bool binary : {false, true}) {
    const std::string path = dir.file(binary ? "b.ply" : "a.ply");
    write_mesh(path, m, binary);
    expect_identical(m, read_mesh(path));
  }
}

// Every truncation and many single-byte corruptions of a valid file either read or give a gps::Error:
// never a crash, a hang or another exception.
TEST(PlyIo, TruncatedAndCorruptedFilesNeverCrash) {
  const CovarianceMesh m = make_sample("cube");
  for (const bool binary : {false, true}) {
    std::ostringstream out;
    write_ply(out, m, binary);
    const std::string data = out.str();
    // (An ASCII file cut just before its final newline is still complete.)
    for (size_t n = 0; n + (binary ? 0 : 1) < data.size(); ++n)
      EXPECT_THROW(parse_ply(data.substr(0, n), "cut.ply"), Error) << n;
    std::mt19937 rng(binary ? 7 : 8);
    for (int trial = 0; trial < 2000; ++trial) {
      std::string bad = data;
      const size_t at = rng() % bad.size();
      bad[at] = binary ? char(rng()) : "0123456789 .-e\nnax"[rng() % 19];
      try {
        parse_ply(bad, "bad.ply");
      } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
      }
    }
  }
}

}  // namespace
}  // namespace gps
