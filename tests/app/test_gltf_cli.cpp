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
