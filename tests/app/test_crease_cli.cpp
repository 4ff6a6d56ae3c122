// Creases and corners from the command line: info counts them, infer --crease-angle marks folded
// edges, edit sets them, and a save keeps them exactly.
#include <gtest/gtest.h>

#include <fstream>

#include "core/io/mesh_io.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

using test::gpsurf;
using test::run_command;

const std::string kData = GPS_TEST_DATA_DIR;

// An axis-aligned unit cube as a plain OBJ: every edge has a dihedral angle of 90°.
std::string write_cube(const test::TempDir& dir) {
  return dir.write("cube.obj",
                   "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                   "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
}

TEST(CreaseCli, DataFilesHoldWhatTheirCommentsSay) {
  const CovarianceMesh cube = read_mesh(kData + "/creased_cube.ply");
  Sharpness top;
  top.creases = {{4, 5, 10.0}, {4, 7, 10.0}, {5, 6, 10.0}, {6, 7, 10.0}};
  EXPECT_EQ(cube.sharpness, top);
  const CovarianceMesh cylinder = read_mesh(kData + "/creased_cylinder.ply");
  EXPECT_EQ(cylinder.sharpness.crease(0, 1), 0.5);
  EXPECT_EQ(cylinder.sharpness.crease(2, 1), 1.0);
  EXPECT_EQ(cylinder.sharpness.crease(3, 2), 2.5);
  EXPECT_EQ(cylinder.sharpness.crease(3, 4), 4.7);
  EXPECT_EQ(cylinder.sharpness.crease(8, 16), 1.0);
  EXPECT_EQ(cylinder.sharpness.crease(23, 16), kInfiniteSharpness);
  EXPECT_EQ(cylinder.sharpness.corner(0), 3.0);
  EXPECT_EQ(cylinder.sharpness.corner(20), kInfiniteSharpness);
}

TEST(CreaseCli, InfoCountsCreasesAndCorners) {
  const auto cylinder = run_command(gpsurf("info " + kData + "/creased_cylinder.ply"));
  ASSERT_EQ(cylinder.exit_code, 0) << cylinder.output;
  EXPECT_NE(cylinder.output.find("creased edges: 13 (5 semi-sharp, 8 infinitely sharp)\n"), std::string::npos)
      << cylinder.output;
  EXPECT_NE(cylinder.output.find("corners: 2 (1 semi-sharp, 1 infinitely sharp)\n"), std::string::npos)
      << cylinder.output;
  test::TempDir dir;
  const auto smooth = run_command(gpsurf("info " + write_cube(dir)));
  EXPECT_NE(smooth.output.find("creased edges: 0 (0 semi-sharp, 0 infinitely sharp)\n"), std::string::npos)
      << smooth.output;
}

TEST(CreaseCli, InferCreaseAngleMarksTheCubesEdges) {
  test::TempDir dir;
  const std::string cube = write_cube(dir);
  const auto sharp = run_command(gpsurf("infer " + cube + " -o " + dir.file("sharp.ply") + " --crease-angle 30"));
  ASSERT_EQ(sharp.exit_code, 0) << sharp.output;
  EXPECT_NE(sharp.output.find("creased 12 edges folded by more than 30 degrees"), std::string::npos) << sharp.output;
  const CovarianceMesh m = read_mesh(dir.file("sharp.ply"));
  ASSERT_EQ(m.sharpness.creases.size(), 12u);
  for (const EdgeCrease& c : m.sharpness.creases) EXPECT_EQ(c.sharpness, kInfiniteSharpness);

  const auto none = run_command(gpsurf("infer " + cube + " -o " + dir.file("none.ply") + " --crease-angle 95"));
  ASSERT_EQ(none.exit_code, 0) << none.output;
  EXPECT_NE(none.output.find("creased 0 edges"), std::string::npos) << none.output;
  EXPECT_TRUE(read_mesh(dir.file("none.ply")).sharpness.empty());
  EXPECT_EQ(test::file_text(dir.file("none.ply")).find("element edge"), std::string::npos);

  const auto wide = run_command(gpsurf("infer " + cube + " -o " + dir.file("x.ply") + " --crease-angle 200"));
  EXPECT_EQ(wide.exit_code, 2);
  EXPECT_NE(wide.output.find("--crease-angle: expected a number from 0 to 180, got '200'"), std::string::npos)
      << wide.output;
}

TEST(CreaseCli, EditSetsCreasesAndCorners) {
  test::TempDir dir;
  const auto r = run_command(
      gpsurf("edit " + kData + "/creased_cube.ply -o " + dir.file("e.ply") +
             R"( --ops '[{"op":"crease","edges":[[4,5]],"sharpness":0},)"
             R"({"op":"crease","edges":[[0,1]],"sharpness":2.5},{"op":"corner","vertices":[3],"sharpness":1}]')"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("ops[1]: set the crease of 1 edge to 2.5"), std::string::npos) << r.output;
  const CovarianceMesh m = read_mesh(dir.file("e.ply"));
  Sharpness expected;
  expected.creases = {{0, 1, 2.5}, {4, 7, 10.0}, {5, 6, 10.0}, {6, 7, 10.0}};
  expected.corners = {0, 0, 0, 1, 0, 0, 0, 0};
  EXPECT_EQ(m.sharpness, expected);

  const auto refused = run_command(gpsurf("edit " + kData + "/creased_cube.ply -o " + dir.file("r.ply") +
                                          R"( --ops '[{"op":"crease","edges":[[0,6]],"sharpness":1}]')"));
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.output.find("ops[0] (crease): edge 0–6 is not in the mesh"), std::string::npos) << refused.output;
}

TEST(CreaseCli, SavingKeepsSharpnessByteExact) {
  test::TempDir dir;
  const std::string in = kData + "/creased_cylinder.ply";
  const std::string no_op = R"( --ops '[{"op":"corner","vertices":[5],"sharpness":0}]')";
  for (const std::string format : {"", " --ascii"}) {
    const std::string a = dir.file("a.ply"), b = dir.file("b.ply");
    ASSERT_EQ(run_command(gpsurf("edit " + in + " -o " + a + no_op + format)).exit_code, 0);
    ASSERT_EQ(run_command(gpsurf("edit " + a + " -o " + b + no_op + format)).exit_code, 0);
    EXPECT_EQ(test::file_text(a), test::file_text(b)) << format;
    EXPECT_EQ(read_mesh(b).sharpness, read_mesh(in).sharpness) << format;
  }
}

}  // namespace
}  // namespace gps
