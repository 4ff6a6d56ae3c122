// gpsurf compare as a user runs it: a known offset from a planar limit surface, --both, and errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <tuple>
#include <vector>

#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

using test::gpsurf;
using test::run_command;

/// An n × n grid of squares of side `cell` from (origin, origin), split into triangles, in the plane z = height.
std::string flat_grid_obj(int n, double cell, double origin, double height) {
  std::ostringstream obj;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) obj << "v " << origin + cell * i << " " << origin + cell * j << " " << height << "\n";
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int a = i * (n + 1) + j + 1;
      obj << "f " << a << " " << a + n + 1 << " " << a + n + 2 << "\nf " << a << " " << a + n + 2 << " " << a + 1
          << "\n";
    }
  return obj.str();
}

TEST(CompareCli, PointsOffsetFromAFlatLimitSurfaceAreTheOffsetAway) {
  test::TempDir dir;
  // B's limit surface lies in z = 0 (flat Gaussians) and covers [0, 4]² but near its corners, which
  // it rounds off; A's vertices lie over its middle [1, 3]² at height 0.25, A's diagonal 2√2.
  const std::string a = dir.write("a.obj", flat_grid_obj(4, 0.5, 1, 0.25));
  const std::string b = dir.write("b.obj", flat_grid_obj(4, 1, 0, 0));
  const auto r = run_command(gpsurf("compare " + a + " " + b));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("(25 vertices) to the limit surface of"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\nrms 0.25 (8.839e-02 of the diagonal)\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\n99th percentile 0.25 (8.839e-02 of the diagonal)\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\nmax 0.25 (8.839e-02 of the diagonal)\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\nnormals: rms angle 0° (max 0°) over 25 points\n"), std::string::npos) << r.output;

  const auto both = run_command(gpsurf("compare " + a + " " + b + " --both --level 4"));
  ASSERT_EQ(both.exit_code, 0) << both.output;
  EXPECT_EQ(std::count(both.output.begin(), both.output.end(), '\n'), 10) << both.output;
  EXPECT_NE(both.output.find("b.obj (25 vertices) to the limit surface of"), std::string::npos) << both.output;

  const auto samples = run_command(gpsurf("compare " + a + " " + b + " --samples --level 2"));
  ASSERT_EQ(samples.exit_code, 0) << samples.output;
  EXPECT_NE(samples.output.find("limit samples) to the limit surface of"), std::string::npos) << samples.output;
  EXPECT_NE(samples.output.find("\nmax 0.25 "), std::string::npos) << samples.output;
}

// The rms angle between A's normals (of its faces, as lines) and B's limit normals at the nearest
// points: a grid tilted by 30° about x over a flat surface turns 30°, whichever way its faces run; a
// vertex on no face has no normal to compare, and is counted as left out.
TEST(CompareCli, NormalsAreComparedAsLines) {
  test::TempDir dir;
  const std::string b = dir.write("b.obj", flat_grid_obj(4, 1, 0, 0));
  std::ostringstream tilted, reversed;
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 2; ++j) {
      const double y = 0.5 * j - 0.5;
      const std::string v = "v " + std::to_string(1.5 + 0.5 * i) + " " + std::to_string(2 + c * y) + " " +
                            std::to_string(0.5 + s * y) + "\n";
      tilted << v;
      reversed << v;
    }
  tilted << "v 2 2 3\n";
  tilted << "f 1 4 5 2\nf 2 5 6 3\nf 4 7 8 5\nf 5 8 9 6\n";
  reversed << "f 1 2 5 4\nf 2 3 6 5\nf 4 5 8 7\nf 5 6 9 8\n";
  for (const auto& [name, text, line] : std::vector<std::tuple<std::string, std::string, std::string>>{
           {"tilted.obj", tilted.str(),
            "\nnormals: rms angle 30° (max 30°) over 9 points (1 without a normal left out: on a sharp edge or corner, "
            "or on no face)\n"},
           {"reversed.obj", reversed.str(), "\nnormals: rms angle 30° (max 30°) over 9 points\n"}}) {
    const auto r = run_command(gpsurf("compare " + dir.write(name, text) + " " + b + " --level 4"));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find(line), std::string::npos) << name << ": " << r.output;
  }
}

// A roof of two slopes of 40° over a flat surface: the vertices on either slope turn 40° from it, and
// those on the ridge, whose faces turn 40° either way from their average, have no one normal (the
// average, level, would pass for the flat surface's): they are left out.
TEST(CompareCli, VerticesOnASharpEdgeAreLeftOutOfTheNormals) {
  test::TempDir dir;
  const std::string b = dir.write("b.obj", flat_grid_obj(4, 1, 0, 0));
  std::ostringstream roof;
  const double c = std::cos(40 * M_PI / 180), s = std::sin(40 * M_PI / 180);
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 2; ++i)
      roof << "v " << 1.5 + 0.5 * i << " " << 2 + 0.5 * c * (j - 1) << " " << 0.5 + 0.5 * s * (j == 1) << "\n";
  roof << "f 1 2 5 4\nf 2 3 6 5\nf 4 5 8 7\nf 5 6 9 8\n";
  const auto r = run_command(gpsurf("compare " + dir.write("roof.obj", roof.str()) + " " + b + " --level 4"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("\nnormals: rms angle 40° (max 40°) over 6 points (3 without a normal left out: on a sharp "
                          "edge or corner, or on no face)\n"),
            std::string::npos)
      << r.output;
}

TEST(CompareCli, LinearMeasuresToTheFacesThemselves) {
  test::TempDir dir;
  // An octahedron's vertices lie on its own faces, but off its limit surface, which subdivision
  // shrinks towards the centre.
  const std::string octahedron = dir.write("octahedron.obj",
                                           "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
                                           "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n");
  const auto linear = run_command(gpsurf("compare " + octahedron + " " + octahedron + " --linear"));
  ASSERT_EQ(linear.exit_code, 0) << linear.output;
  EXPECT_NE(linear.output.find("(6 vertices) to the faces of"), std::string::npos) << linear.output;
  EXPECT_NE(linear.output.find("\nmax 0 (0.000e+00 of the diagonal)\n"), std::string::npos) << linear.output;
  const auto limit = run_command(gpsurf("compare " + octahedron + " " + octahedron));
  ASSERT_EQ(limit.exit_code, 0) << limit.output;
  EXPECT_EQ(limit.output.find("\nmax 0 "), std::string::npos) << limit.output;
  EXPECT_EQ(run_command(gpsurf("compare " + octahedron + " " + octahedron + " --linear --samples")).exit_code, 2);
}

/// Two unit cubes over [1, 3]² from z = `bottom` to `bottom` + 0.25 sharing their vertical edge at (2, 2):
/// 14 vertices, and the shared edge in four faces (a fin), so not a manifold.
std::string cubes_sharing_an_edge_obj(double bottom) {
  std::ostringstream obj;
  const double top = bottom + 0.25;
  for (const double z : {bottom, top})  // vertices 1-7 at the bottom, 8-14 at the top
    obj << "v 1 1 " << z << "\nv 2 1 " << z << "\nv 2 2 " << z << "\nv 1 2 " << z << "\nv 3 2 " << z << "\nv 3 3 " << z
        << "\nv 2 3 " << z << "\n";
  for (const auto& q : {std::array<int, 4>{1, 4, 3, 2}, {3, 7, 6, 5}})  // each cube: bottom, top, four sides
    obj << "f " << q[0] << " " << q[1] << " " << q[2] << " " << q[3] << "\nf " << q[0] + 7 << " " << q[3] + 7 << " "
        << q[2] + 7 << " " << q[1] + 7 << "\n";
  for (const auto& ring : {std::array<int, 4>{1, 2, 3, 4}, {3, 5, 6, 7}})
    for (int k = 0; k < 4; ++k) {
      const int a = ring[size_t(k)], b = ring[size_t((k + 1) % 4)];
      obj << "f " << a << " " << b << " " << b + 7 << " " << a + 7 << "\n";
    }
  return obj.str();
}

// A first mesh that is not a manifold (a scan's fins) is measured as its points: its 14 vertices, 7 at
// height 0.25 and 7 at 0.5 over B's flat limit surface. Where its surface is needed (--both) it is
// refused naming the fin; --repair mends B, and its line names the file.
TEST(CompareCli, ANonManifoldFirstMeshIsMeasuredAsItsPoints) {
  test::TempDir dir;
  const std::string a = dir.write("cubes.obj", cubes_sharing_an_edge_obj(0.25));
  const std::string b = dir.write("b.obj", flat_grid_obj(4, 1, 0, 0));
  const auto r = run_command(gpsurf("compare " + a + " " + b));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("cubes.obj (14 vertices) to the limit surface of"), std::string::npos) << r.output;
  const double rms = std::sqrt((7 * 0.25 * 0.25 + 7 * 0.5 * 0.5) / 14);
  std::ostringstream expected_rms;
  expected_rms << "\nrms " << rms << " (";
  EXPECT_NE(r.output.find(expected_rms.str()), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\nmax 0.5 ("), std::string::npos) << r.output;

  const auto both = run_command(gpsurf("compare " + a + " " + b + " --both --level 2"));
  EXPECT_EQ(both.exit_code, 1) << both.output;
  EXPECT_EQ(std::count(both.output.begin(), both.output.end(), '\n'), 1) << both.output;
  EXPECT_NE(both.output.find("cubes.obj: 1 non-manifold edge (a fin"), std::string::npos) << both.output;

  const auto repaired = run_command(gpsurf("compare " + a + " " + b + " --repair"));
  ASSERT_EQ(repaired.exit_code, 0) << repaired.output;
  EXPECT_EQ(repaired.output.rfind("repair: " + b + ": nothing to repair\n", 0), 0u) << repaired.output;
  EXPECT_EQ(repaired.output.find("repair: " + a), std::string::npos) << repaired.output;
}

// A file of vertices alone, in any format, is points to measure; points at one place span no length,
// so their distances have no figure relative to it.
TEST(CompareCli, PointCloudsOfEveryFormatAreMeasured) {
  test::TempDir dir;
  const std::string b = dir.write("b.obj", flat_grid_obj(4, 1, 0, 0));
  const std::string obj = dir.write("cloud.obj", "v 1 1 0.25\nv 2 2 0.25\nv 3 1 0.25\n");
  const std::string off = dir.write("cloud.off", "OFF\n3 0 0\n1 1 0.25\n2 2 0.25\n3 1 0.25\n");
  for (const std::string& a : {obj, off}) {
    const auto r = run_command(gpsurf("compare " + a + " " + b));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("(3 vertices) to the limit surface of"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("\nrms 0.25 ("), std::string::npos) << r.output;
  }
  const std::string one = dir.write("one.obj", "v 2 2 0.25\nv 2 2 0.25\nv 2 2 0.25\nf 1 2 3\n");
  const auto r = run_command(gpsurf("compare " + one + " " + b));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("\nrms 0.25 (the points measured span no length)\n"), std::string::npos) << r.output;
}

TEST(CompareCli, UsageAndRuntimeErrorsAreOneLine) {
  test::TempDir dir;
  const std::string a = dir.write("a.obj", flat_grid_obj(2, 1, 0, 0));
  for (const std::string& args : {a, a + " " + a + " --level 0", a + " " + a + " --scheme nonsense"}) {
    const auto r = run_command(gpsurf("compare " + args));
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << args << ": " << r.output;
  }
  const auto missing = run_command(gpsurf("compare " + a + " " + dir.file("none.ply")));
  EXPECT_EQ(missing.exit_code, 1) << missing.output;
  EXPECT_EQ(std::count(missing.output.begin(), missing.output.end(), '\n'), 1) << missing.output;
  EXPECT_NE(missing.output.find("none.ply"), std::string::npos) << missing.output;
}

}  // namespace
}  // namespace gps
