// gpsurf tessellate as a user runs it: PLY with normals, OBJ, usage errors (exit 2), runtime errors (exit 1).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

using test::gpsurf;
using test::run_command;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(TessellateCli, WritesPlyWithNormalsAndObj) {
  test::TempDir dir;
  ASSERT_EQ(run_command(gpsurf("sample cube -o " + dir.file("cube.ply"))).exit_code, 0);
  const auto r =
      run_command(gpsurf("tessellate " + dir.file("cube.ply") + " -o " + dir.file("t.ply") + " --depth 2 --level 4"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // 6 patches at level 4, welded: V = 6·3² + 12·3 + 8 = 98, F = 6·4²·2 = 192.
  EXPECT_NE(r.output.find("98 vertices, 192 triangles"), std::string::npos) << r.output;
  const std::string ply = slurp(dir.file("t.ply"));
  EXPECT_NE(ply.find("element vertex 98"), std::string::npos);
  EXPECT_NE(ply.find("property double nx"), std::string::npos);
  EXPECT_EQ(
      run_command(gpsurf("tessellate " + dir.file("cube.ply") + " -o " + dir.file("t.obj") + " --level 2")).exit_code,
      0);
  EXPECT_NE(slurp(dir.file("t.obj")).find("vn "), std::string::npos);
}

TEST(TessellateCli, UsageAndRuntimeErrors) {
  test::TempDir dir;
  ASSERT_EQ(run_command(gpsurf("sample cube -o " + dir.file("cube.ply"))).exit_code, 0);
  for (const std::string& args : {std::string("--depth 9"), std::string("--approximate --depth 0"),
                                  std::string("--level 0"), std::string("--level 65")}) {
    const auto r = run_command(gpsurf("tessellate " + dir.file("cube.ply") + " -o " + dir.file("x.ply") + " " + args));
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  }
  const auto missing = run_command(gpsurf("tessellate " + dir.file("none.ply") + " -o " + dir.file("x.ply")));
  EXPECT_EQ(missing.exit_code, 1) << missing.output;
  EXPECT_NE(missing.output.find("none.ply"), std::string::npos) << missing.output;
}

// A face the plans refuse is named as its file numbers it: an OBJ's from 1 with its line, a PLY's
// from 0; after --repair (which renumbers) from 0.
TEST(TessellateCli, AFaceThePlansRefuseIsNamedAsTheFileNumbersIt) {
  test::TempDir dir;
  std::string obj = "# one face of 300 sides\n";
  for (int k = 0; k < 300; ++k)
    obj += "v " + std::to_string(std::cos(k * 2 * M_PI / 300)) + " " + std::to_string(std::sin(k * 2 * M_PI / 300)) +
           " 0\n";
  obj += "f";
  for (int k = 1; k <= 300; ++k) obj += " " + std::to_string(k);
  const std::string path = dir.write("wide.obj", obj + "\n");
  const auto r = run_command(gpsurf("tessellate " + path + " -o " + dir.file("t.ply")));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("wide.obj: face 1 (line 302) has 300 sides"), std::string::npos) << r.output;
  ASSERT_EQ(run_command(gpsurf("edit " + path + " -o " + dir.file("wide.ply") + " --ops '[]'")).exit_code, 0);
  const auto ply = run_command(gpsurf("tessellate " + dir.file("wide.ply") + " -o " + dir.file("t.ply")));
  EXPECT_NE(ply.output.find("wide.ply: face 0 has 300 sides"), std::string::npos) << ply.output;
  const auto repaired = run_command(gpsurf("tessellate " + path + " --repair -o " + dir.file("t.ply")));
  EXPECT_NE(repaired.output.find("wide.obj: face 0 has 300 sides"), std::string::npos) << repaired.output;
  EXPECT_FALSE(std::filesystem::exists(dir.file("t.ply")));
}

}  // namespace
}  // namespace gps
