// Outputs sized before the work, as a user meets them: `subdivide`, `tessellate`, `compare` and `fit`
// refuse what exceeds the memory budget (GPSURF_MEMORY_LIMIT_BYTES, small here) with the figures and exit 2, and
// an allocation that fails anyway ends in one line naming the input, exit 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "tests/support/run_command.h"
#include "tests/support/sanitized_build.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

using test::gpsurf;
using test::run_command;

// A refusal before the work: a usage error (exit 2) of one line that gives `figures`.
void expect_sized_refusal(const test::CommandResult& r, const std::string& figures) {
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(test::line_count(r.output), 1u) << r.output;
  EXPECT_NE(r.output.find(figures), std::string::npos) << r.output;
}

TEST(OutputLimitsCli, SubdivideAndTessellateRefuseWhatExceedsTheBudget) {
  test::TempDir dir;
  const std::string cube = dir.file("cube.ply");
  ASSERT_EQ(run_command(gpsurf("sample cube -o " + cube)).exit_code, 0);
  const std::string tight = "GPSURF_MEMORY_LIMIT_BYTES=100000 ";
  const auto subdivided = run_command(tight + gpsurf("subdivide " + cube + " -o " + dir.file("s.ply") + " --levels 4"));
  EXPECT_EQ(subdivided.exit_code, 2) << subdivided.output;
  EXPECT_EQ(test::line_count(subdivided.output), 1u) << subdivided.output;
  EXPECT_EQ(subdivided.output.rfind("gpsurf: " + cube +
                                        ": 4 levels of Catmull-Clark subdivision would make about 1,538 vertices and "
                                        "1,536 faces and hold about ",
                                    0),
            0u)
      << subdivided.output;
  EXPECT_NE(subdivided.output.find("more than the 97.7 KiB allowed (set by GPSURF_MEMORY_LIMIT_BYTES)"),
            std::string::npos)
      << subdivided.output;
  const auto tessellated =
      run_command(tight + gpsurf("tessellate " + cube + " -o " + dir.file("t.ply") + " --level 64"));
  expect_sized_refusal(
      tessellated, cube + ": tessellating 6 patches at level 64 would make about 25,350 vertices and 49,152 triangles");
  EXPECT_FALSE(std::filesystem::exists(dir.file("s.ply")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("t.ply")));
  // Within the budget both run; a malformed budget is a usage error.
  EXPECT_EQ(run_command(tight + gpsurf("subdivide " + cube + " -o " + dir.file("s.ply") + " --levels 2")).exit_code, 0);
  EXPECT_EQ(run_command(tight + gpsurf("tessellate " + cube + " -o " + dir.file("t.ply") + " --level 4")).exit_code, 0);
  const auto malformed =
      run_command("GPSURF_MEMORY_LIMIT_BYTES=lots " + gpsurf("subdivide " + cube + " -o " + dir.file("s.ply")));
  EXPECT_EQ(malformed.exit_code, 2) << malformed.output;
  EXPECT_NE(malformed.output.find("GPSURF_MEMORY_LIMIT_BYTES: expected a positive whole number of bytes, got 'lots'"),
            std::string::npos)
      << malformed.output;
}

// Where the estimate allows more than the process may take (here a virtual memory limit of the
// shell), the failed allocation is one line naming the input, not "std::bad_alloc".

// compare and fit size the search tree of the triangles they measure to with the triangles: a budget
// that the tessellation alone fits but not its tree refuses them before the work, naming the figures.
TEST(OutputLimitsCli, CompareAndFitSizeTheirSearchTreesWithTheTriangles) {
  test::TempDir dir;
  const std::string cube = dir.file("cube.ply"), finer = dir.file("finer.ply"), point = dir.file("point.ply");
  ASSERT_EQ(run_command(gpsurf("sample cube -o " + cube)).exit_code, 0);
  ASSERT_EQ(run_command(gpsurf("subdivide " + cube + " -o " + finer + " --levels 3")).exit_code, 0);
  dir.write("point.ply",
            "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
            "property float z\nend_header\n0.1 0.2 0.3\n");
  const std::string budget = "GPSURF_MEMORY_LIMIT_BYTES=5000000 ";  // the 6 patches' tessellation at 64 fits
  const auto compared = run_command(budget + gpsurf("compare " + cube + " " + cube + " --level 64"));
  expect_sized_refusal(compared, cube +
                                     ": measuring distances to 6 patches tessellated at level 64 would make about "
                                     "25,350 vertices and 49,152 triangles and hold about ");
  const auto fitted =
      run_command(budget + gpsurf("fit " + finer + " --target " + point + " -o " + dir.file("f.ply") + " --level 0"));
  EXPECT_EQ(fitted.exit_code, 2) << fitted.output;
  EXPECT_NE(fitted.output.find(": finding the closest points on 384 patches tessellated at level 6 would make about "
                               "18,816 vertices and 27,648 triangles and hold about "),
            std::string::npos)
      << fitted.output;
  EXPECT_FALSE(std::filesystem::exists(dir.file("f.ply")));
  EXPECT_EQ(run_command(budget + gpsurf("compare " + cube + " " + cube + " --level 8")).exit_code, 0);
}
TEST(OutputLimitsCli, RunningOutOfMemoryNamesTheInput) {
#if defined(GPS_SANITIZED)
  GTEST_SKIP() << "AddressSanitizer reserves more address space than the limit allows";
#else
  test::TempDir dir;
  const std::string sphere = dir.file("sphere.ply");
  ASSERT_EQ(run_command(gpsurf("sample sphere --size 2000 -o " + sphere)).exit_code, 0);
  // About 8 million samples at level 64: their positions, normals and triangles alone take more
  // than the 500 MB of address space allowed.
  const auto r = run_command("ulimit -v 500000 && OMP_NUM_THREADS=1 GPSURF_MEMORY_LIMIT_BYTES=1000000000000 " +
                             gpsurf("tessellate " + sphere + " -o " + dir.file("t.ply") + " --level 64"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_EQ(r.output, "gpsurf: " + sphere + ": out of memory in tessellate\n");
  EXPECT_FALSE(std::filesystem::exists(dir.file("t.ply")));
#endif
}

}  // namespace
}  // namespace gps
