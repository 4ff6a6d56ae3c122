// glTF on the command line: a covariance mesh written as .glb is read by info, subdivide and tessellate,
// and tessellate writes its limit surface as .glb; a broken .glb is one line and exit 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "core/io/mesh_io.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

using test::gpsurf;
using test::run_command;

TEST(GltfCli, InfoSubdivideAndTessellateReadAndWriteGlb) {
  test::TempDir dir;
  const std::string cube = dir.file("cube.glb");
  ASSERT_EQ(run_command(gpsurf("sample cube -o " + cube)).exit_code, 0);
  const auto info = run_command(gpsurf("info " + cube));
  ASSERT_EQ(info.exit_code, 0) << info.output;
  // The cube's quads come back as 12 triangles on its 8 vertices.
  EXPECT_NE(info.output.find("vertices: 8\n"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("faces: 12 (12 with 3 sides)"), std::string::npos) << info.output;

  const auto sub = run_command(gpsurf("subdivide " + cube + " -o " + dir.file("y.ply")));
  ASSERT_EQ(sub.exit_code, 0) << sub.output;
  EXPECT_GT(read_mesh(dir.file("y.ply")).n_faces(), 12u);

  const auto tess = run_command(gpsurf("tessellate " + cube + " -o " + dir.file("t.glb") + " --level 2"));
  ASSERT_EQ(tess.exit_code, 0) << tess.output;
  // The tessellation is watertight: read back, its welded vertices and triangles are the ones it reported.
  const CovarianceMesh t = read_mesh(dir.file("t.glb"));
  EXPECT_NE(
      tess.output.find(std::to_string(t.n_vertices()) + " vertices, " + std::to_string(t.n_faces()) + " triangles"),
      std::string::npos)
      << tess.output;
}

// Creases and corners saved as glTF, which has no place for them, are named in a note (not with
// --quiet); a mesh without them, or a save as .ply, gets none.
TEST(GltfCli, CreasesAndCornersAGlbCannotKeepAreNoted) {
  test::TempDir dir;
  const std::string obj = dir.write("c.obj",
                                    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                                    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n"
                                    "t crease 2/1/0 1 2 2.0\nt corner 1/1/0 4 10\n");
  const std::string note = "c.glb: 1 crease and 1 corner not saved (glTF has no place for them";
  const auto glb = run_command(gpsurf("edit " + obj + " -o " + dir.file("c.glb") + " --ops []"));
  ASSERT_EQ(glb.exit_code, 0) << glb.output;
  EXPECT_NE(glb.output.find("note: " + dir.file(note)), std::string::npos) << glb.output;
  const auto quiet = run_command(gpsurf("edit " + obj + " -o " + dir.file("c.glb") + " --ops [] -q"));
  EXPECT_EQ(quiet.output, "");
  const auto ply = run_command(gpsurf("edit " + obj + " -o " + dir.file("c.ply") + " --ops []"));
  EXPECT_EQ(ply.output.find("note:"), std::string::npos) << ply.output;
  const auto plain = run_command(gpsurf("sample cube -o " + dir.file("cube.ply")));
  const auto none = run_command(gpsurf("infer " + dir.file("cube.ply") + " -o " + dir.file("cube.glb")));
  EXPECT_EQ(none.output.find("note:"), std::string::npos) << none.output;
}

TEST(GltfCli, BrokenGlbIsOneLineAndExit1) {
  test::TempDir dir;
  const std::string cube = dir.file("cube.glb");
  ASSERT_EQ(run_command(gpsurf("sample cube -o " + cube)).exit_code, 0);
  std::ifstream in(cube, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  const std::string cut = dir.write("cut.glb", bytes.str().substr(0, bytes.str().size() / 2));
  const auto r = run_command(gpsurf("info " + cut));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_NE(r.output.find("cut.glb"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace gps
