// Every command that writes a mesh writes binary little-endian PLY unless asked for --ascii, and
// both hold the same mesh exactly (doubles in either).
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/io/mesh_io.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

using test::gpsurf;
using test::run_command;

// The second line of a PLY file: its format.
std::string format_line(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string magic, format;
  std::getline(in, magic);
  std::getline(in, format);
  return format;
}

void expect_same_mesh(const CovarianceMesh& a, const CovarianceMesh& b, const std::string& what) {
  ASSERT_EQ(a.n_vertices(), b.n_vertices()) << what;
  ASSERT_EQ(a.n_faces(), b.n_faces()) << what;
  for (size_t i = 0; i < a.n_vertices(); ++i) {
    EXPECT_EQ(a.mean(i), b.mean(i)) << what << " vertex " << i;
    EXPECT_EQ(a.covariance(i), b.covariance(i)) << what << " vertex " << i;
  }
  EXPECT_EQ(a.sharpness, b.sharpness) << what;
}

TEST(OutputFormatCli, MeshesAreBinaryByDefaultAndTextWithAscii) {
  test::TempDir dir;
  const std::string ico = dir.file("ico.ply"), cube = dir.file("cube.ply");
  ASSERT_EQ(run_command(gpsurf("sample icosphere --size 80 -o " + ico)).exit_code, 0);
  ASSERT_EQ(run_command(gpsurf("sample cube -o " + cube)).exit_code, 0);
  const std::string commands[] = {
      "sample cube",
      "infer " + ico,
      "subdivide " + cube + " --levels 2",
      "tessellate " + cube + " --level 3",
      "edit " + cube + R"( --ops '[{"op":"corner","vertices":[1],"sharpness":2}]')",
      "simplify " + ico + " --ratio 0.5 --level 0",
  };
  for (const std::string& command : commands) {
    const std::string binary = dir.file("binary.ply"), text = dir.file("text.ply");
    const auto b = run_command(gpsurf(command + " -o " + binary));
    ASSERT_EQ(b.exit_code, 0) << command << ": " << b.output;
    const auto t = run_command(gpsurf(command + " -o " + text + " --ascii"));
    ASSERT_EQ(t.exit_code, 0) << command << ": " << t.output;
    EXPECT_EQ(format_line(binary), "format binary_little_endian 1.0") << command;
    EXPECT_EQ(format_line(text), "format ascii 1.0") << command;
    expect_same_mesh(read_mesh(binary), read_mesh(text), command);
  }
}

}  // namespace
}  // namespace gps
