// gpsurf edit: modelling operations from the command line, run as a script would: the operations in
// order on indices of the mesh as it stands, exit 1 and nothing written on a refusal, exit 2 on a
// malformed list, both with one line naming the operation.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/io/mesh_io.h"
#include "core/modelling/samples.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

using test::gpsurf;
using test::run_command;

TEST(EditCli, AppliesOperationsInOrder) {
  test::TempDir dir;
  const std::string ops = dir.file("ops.json");
  std::ofstream(ops) << R"([
    {"op": "loop_cut", "edge": [0, 1]},
    {"op": "extrude", "faces": [1], "distance": 0.5},
    {"op": "transform", "vertices": "all", "matrix": [2,0,0,0, 0,2,0,0, 0,0,2,0, 0,0,0,1]},
    {"op": "add", "primitive": "cube", "center": [5, 0, 0], "size": 1}
  ])";
  const auto r = run_command(gpsurf("edit sample:cube -o " + dir.file("out.ply") + " --ops @" + ops));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("ops[1]: extruded"), std::string::npos) << r.output;
  const CovarianceMesh m = read_mesh(dir.file("out.ply"));
  // Cube 8/6, loop cut +4/+4, extruding one quad +4/+4, a cube +8/+6.
  EXPECT_EQ(m.n_vertices(), 24u);
  EXPECT_EQ(m.n_faces(), 20u);
  EXPECT_TRUE(m.mean(0).isApprox(Vec3(-2, -2, -2), 1e-15));
  const CovarianceMesh cube = make_sample("cube");
  EXPECT_TRUE(m.covariance(0).isApprox(4.0 * cube.covariance(0), 1e-14));
}

TEST(EditCli, InlineOperations) {
  test::TempDir dir;
  const auto r = run_command(gpsurf("edit sample:cube -o " + dir.file("s.ply") + " --ops '[{\"op\":\"subdivide\"}]'"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read_mesh(dir.file("s.ply")).n_faces(), 24u);
}

TEST(EditCli, RefusedOperationWritesNothing) {
  test::TempDir dir;
  const std::string out = dir.file("out.ply");
  std::ofstream(out) << "precious";
  const auto r = run_command(gpsurf("edit sample:cube -o " + out +
                                    R"( --ops '[{"op":"loop_cut","edge":[0,1]},{"op":"merge","vertices":[0,99]}]')"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_EQ(test::line_count(r.output), 1u) << r.output;
  EXPECT_NE(r.output.find("ops[1] (merge): vertex 99 is not in the mesh (12 vertices)"), std::string::npos) << r.output;
  EXPECT_EQ(test::file_text(out), "precious");
}

// A run of whole-mesh subdivisions is sized before the first of them: beyond the memory budget it is
// refused at once with its figures (exit 2), nothing written.
TEST(EditCli, WholeMeshSubdivisionsBeyondTheBudgetAreRefusedBeforeAny) {
  test::TempDir dir;
  std::string ops = "[";
  for (int i = 0; i < 12; ++i) ops += std::string(i ? "," : "") + "{\"op\":\"subdivide\"}";
  dir.write("ops.json", ops + "]");
  const auto r = run_command("GPSURF_MEMORY_LIMIT_BYTES=100000000 " +
                             gpsurf("edit sample:cube -o " + dir.file("s.ply") + " --ops @" + dir.file("ops.json")));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("ops.json: ops[0] (subdivide): 12 whole-mesh subdivisions (ops[0] to ops[11]) would make "
                          "about 100,663,298 vertices and 100,663,296 faces and hold about "),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir.file("s.ply")));
}

TEST(EditCli, MalformedOperationsAreUsageErrors) {
  test::TempDir dir;
  const std::string out = dir.file("out.ply");
  const auto run = [&](const std::string& ops) {
    return run_command(gpsurf("edit sample:cube -o " + out + " --ops '" + ops + "'"));
  };
  for (const auto& [ops, message] : std::vector<std::pair<std::string, std::string>>{
           {R"([{"op":"extrude","faces":[1]}])", R"(ops[0] (extrude): "distance" is missing)"},
           {R"([{"op":"loop_cut","edge":[0,1],"cutz":2}])", R"(ops[0] (loop_cut): unknown key 'cutz')"},
           {R"([{"op":"subdivide"},{"op":"twist"}])", "ops[1] ('twist'): unknown operation"},
           {R"([{"op":"transform","vertices":"all","matrix":[1,0,0]}])", "the matrix has 3 numbers"},
           {R"({"op":"subdivide"})", "expected a JSON array"},
           {R"([{"op":"subdivide")", "gpsurf: --ops: not valid JSON"},
           {R"([{"op":"extrude","faces":[0],"distance":NaN}])", "gpsurf: --ops: not valid JSON (byte 41)"},
           {R"([{"op":"extrude","faces":[0],"distance":0}])", R"(ops[0] (extrude): "distance" must not be 0)"},
           {R"([{"op":"loop_cut","edge":[0,1],"slide":1}])", "ops[0] (loop_cut): the slide must be in (−1, 1), got 1"},
           {R"([{"op":"slide","vertex":0,"toward":1,"factor":1.5}])",
            "ops[0] (slide): the slide factor must be in [0, 1], got 1.5"}}) {
    const auto r = run(ops);
    EXPECT_EQ(r.exit_code, 2) << ops << "\n" << r.output;
    EXPECT_EQ(test::line_count(r.output), 1u) << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
  }
  EXPECT_FALSE(std::filesystem::exists(out));
  // A file given without its @: the refusal says how to read it.
  dir.write("ops.json", R"([{"op":"subdivide"}])");
  const auto no_at = run_command(gpsurf("edit sample:cube -o " + out + " --ops " + dir.file("ops.json")));
  EXPECT_EQ(no_at.exit_code, 2) << no_at.output;
  EXPECT_EQ(test::line_count(no_at.output), 1u) << no_at.output;
  EXPECT_NE(no_at.output.find("write --ops @" + dir.file("ops.json")), std::string::npos) << no_at.output;
  const auto missing = run_command(gpsurf("edit sample:cube -o " + out + " --ops @" + dir.file("none.json")));
  EXPECT_NE(missing.exit_code, 0);
  EXPECT_NE(missing.output.find("none.json"), std::string::npos) << missing.output;
}

}  // namespace
}  // namespace gps
