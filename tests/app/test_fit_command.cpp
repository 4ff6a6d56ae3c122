// gpsurf fit as a user runs it: a progress line per iteration, the final report, a readable result,
// --plain, and errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <tuple>

#include "core/io/text_file.h"
#include "tests/support/run_command.h"
#include "tests/support/sphere_points.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

using test::gpsurf;
using test::run_command;

TEST(FitCli, FitsAnIcosphereToSpherePointsWithProgressAndReport) {
  test::TempDir dir;
  const std::string target = dir.write("target.obj", test::sphere_obj(8));
  const std::string coarse = dir.file("coarse.ply"), out = dir.file("fitted.ply");
  ASSERT_EQ(run_command(gpsurf("sample icosphere --size 80 -o " + coarse)).exit_code, 0);
  for (const std::string mode : {"", " --plain"}) {
    const auto r =
        run_command(gpsurf("fit " + coarse + " --target " + target + " -o " + out + " --iterations 3" + mode));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("fitting 42 vertices"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("\niteration 0: rms "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("\niteration 1: rms "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("target points to the fitted limit surface (level "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("\nmax "), std::string::npos) << r.output;
    const auto info = run_command(gpsurf("info " + out));
    EXPECT_EQ(info.exit_code, 0) << info.output;
    // The icosphere's limit surface shrinks inside the unit sphere; the fit brings it to within 1%.
    const auto compare = run_command(gpsurf("compare " + target + " " + out));
    ASSERT_EQ(compare.exit_code, 0) << compare.output;
    const size_t at = compare.output.find("\nmax ");
    ASSERT_NE(at, std::string::npos);
    EXPECT_LT(std::stod(compare.output.substr(at + 5)), 0.01) << compare.output;
  }
}

TEST(FitCli, StopsAtTheToleranceOrTheTimeAndSaysWhy) {
  test::TempDir dir;
  const std::string target = dir.write("target.obj", test::sphere_obj(8));
  const std::string coarse = dir.file("coarse.ply"), out = dir.file("fitted.ply");
  ASSERT_EQ(run_command(gpsurf("sample icosphere --size 80 -o " + coarse)).exit_code, 0);
  const std::string fit = "fit " + coarse + " --target " + target + " -o " + out + " --level 0 --iterations 50";
  const auto converged = run_command(gpsurf(fit + " --tolerance 0.2"));
  ASSERT_EQ(converged.exit_code, 0) << converged.output;
  EXPECT_NE(converged.output.find(
                " iterations: converged (the rms distance and the objective fell by less than the tolerance)\n"),
            std::string::npos)
      << converged.output;
  EXPECT_EQ(converged.output.find("\niteration 50: "), std::string::npos) << converged.output;
  const auto timed = run_command(gpsurf(fit + " --time 1e-6"));
  ASSERT_EQ(timed.exit_code, 0) << timed.output;
  EXPECT_NE(timed.output.find("\nstopped after 1 iterations: ran out of time\n"), std::string::npos) << timed.output;
  const auto all =
      run_command(gpsurf("fit " + coarse + " --target " + target + " -o " + out + " --level 0 --iterations 2"));
  EXPECT_NE(all.output.find("\nstopped after 2 iterations: ran its iterations\n"), std::string::npos) << all.output;
  for (const std::string bad : {" --tolerance 1.5", " --tolerance -0.1", " --time 0", " --time nan"}) {
    const auto refused = run_command(gpsurf(fit + bad));
    EXPECT_EQ(refused.exit_code, 2) << bad << ": " << refused.output;
    EXPECT_NE(refused.output.find(bad.substr(1, bad.find(' ', 1) - 1)), std::string::npos) << refused.output;
  }
  // A target far from the mesh is refused before the fit stretches the mesh toward its near side.
  const std::string far = dir.file("far.ply");
  ASSERT_EQ(run_command(gpsurf("edit " + coarse + " -o " + far +
                               " --ops '[{\"op\":\"transform\",\"vertices\":\"all\",\"matrix\":"
                               "[1,0,0,1e6, 0,1,0,0, 0,0,1,0, 0,0,0,1]}]'"))
                .exit_code,
            0);
  const auto apart = run_command(gpsurf("fit " + coarse + " --target " + far + " -o " + dir.file("apart.ply")));
  EXPECT_EQ(apart.exit_code, 1) << apart.output;
  EXPECT_NE(apart.output.find("the points to fit lie 999998 from the mesh, "), std::string::npos) << apart.output;
  EXPECT_NE(apart.output.find(" times their size: place the mesh over them first\n"), std::string::npos)
      << apart.output;
  EXPECT_FALSE(std::ifstream(dir.file("apart.ply")).good());
}

// A target that is not a manifold (the sides of two cubes sharing an edge: a fin) is fitted to as its points; with two
// files read, the repair's lines and the reader's notes name the file they are about.
TEST(FitCli, ANonManifoldTargetIsFittedAsItsPoints) {
  test::TempDir dir;
  const std::string coarse = dir.file("coarse.obj");
  ASSERT_EQ(run_command(gpsurf("sample cube -o " + coarse)).exit_code, 0);
  // An edge of the cube's first face creased twice, with two values: the later is kept, with a note.
  std::istringstream written(read_text_file(coarse));
  std::string line;
  while (std::getline(written, line) && line.rfind("f ", 0) != 0) {
  }
  int a = 0, b = 0;
  std::istringstream(line.substr(2)) >> a >> b;  // from 1 in f records, from 0 in tags
  const std::string edge = std::to_string(std::min(a, b) - 1) + " " + std::to_string(std::max(a, b) - 1);
  std::ofstream(coarse, std::ios::app) << "t crease 2/1/0 " << edge << " 1\nt crease 2/1/0 " << edge << " 2\n";
  std::ostringstream target;
  for (const double z : {0.0, 1.0})
    target << "v 0 0 " << z << "\nv 1 0 " << z << "\nv 1 1 " << z << "\nv 0 1 " << z << "\nv 2 1 " << z << "\nv 2 2 "
           << z << "\nv 1 2 " << z << "\n";
  for (const auto& ring : {std::array<int, 4>{1, 2, 3, 4}, {3, 5, 6, 7}})
    for (int k = 0; k < 4; ++k) {  // the sides of two cubes meeting at the edge 3-10: four faces on it
      const int a = ring[size_t(k)], b = ring[size_t((k + 1) % 4)];
      target << "f " << a << " " << b << " " << b + 7 << " " << a + 7 << "\n";
    }
  const std::string cubes = dir.write("cubes.obj", target.str());
  ASSERT_NE(run_command(gpsurf("info " + cubes)).exit_code, 0) << "the target should not be a manifold";
  const std::string out = dir.file("fitted.ply");
  const auto r =
      run_command(gpsurf("fit " + coarse + " --target " + cubes + " -o " + out + " --iterations 1 --level 0 --repair"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find(" to 14 points\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("repair: " + coarse + ": "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("note: " + coarse + ": line "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(": crease " + std::to_string(std::min(a, b) - 1) + "-" + std::to_string(std::max(a, b) - 1) +
                          " repeats line "),
            std::string::npos)
      << r.output;
  EXPECT_EQ(run_command(gpsurf("info " + out)).exit_code, 0);
}

/// The largest covariance eigenvalue that `gpsurf info` reports for a file.
double largest_eigenvalue(const std::string& path) {
  const auto info = run_command(gpsurf("info " + path));
  const size_t at = info.output.find("covariance eigenvalues: ");
  if (info.exit_code != 0 || at == std::string::npos) return NAN;
  const size_t dots = info.output.find(" .. ", at);
  return dots == std::string::npos ? NAN : std::stod(info.output.substr(dots + 4));
}

TEST(FitCli, SigmaBoundsReachTheFitAndAnEmptyRangeIsRefused) {
  test::TempDir dir;
  const std::string target = dir.write("target.obj", test::sphere_obj(8));
  const std::string coarse = dir.file("coarse.ply"), tight = dir.file("tight.ply"), loose = dir.file("loose.ply");
  ASSERT_EQ(run_command(gpsurf("sample icosphere --size 80 -o " + coarse)).exit_code, 0);
  const std::string fit = "fit " + coarse + " --target " + target + " --level 0 --iterations 2 -o ";
  ASSERT_EQ(run_command(gpsurf(fit + tight + " --min-sigma 0.1 --max-sigma 0.2")).exit_code, 0);
  ASSERT_EQ(run_command(gpsurf(fit + loose + " --min-sigma 1 --max-sigma 2")).exit_code, 0);
  // Every standard deviation of the tight fit lies below every one of the loose fit (the icosphere's
  // edges differ by far less than the factor of five between the bounds).
  EXPECT_LT(largest_eigenvalue(tight), 0.25 * largest_eigenvalue(loose));
  const std::string refused_file = dir.file("refused.ply");
  const auto refused = run_command(gpsurf(fit + refused_file + " --min-sigma 2 --max-sigma 1"));
  EXPECT_EQ(refused.exit_code, 2) << "a usage error, naming both options";
  EXPECT_NE(refused.output.find("--min-sigma 2 must be below --max-sigma 1"), std::string::npos) << refused.output;
  EXPECT_FALSE(std::ifstream(refused_file).good());
}

// The relaxation itself, said and asked for once, is fitted in tests/numeric/test_fit_command_relaxation.cpp.
TEST(FitCli, ANegativeRelaxedLowerBoundIsAUsageError) {
  test::TempDir dir;
  const std::string target = dir.write("target.obj", test::sphere_obj(2));
  const std::string coarse = dir.file("coarse.ply"), refused = dir.file("refused.ply");
  ASSERT_EQ(run_command(gpsurf("sample icosphere --size 80 -o " + coarse)).exit_code, 0);
  const auto r =
      run_command(gpsurf("fit " + coarse + " --target " + target + " -o " + refused + " --relaxed-min-sigma -1"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--relaxed-min-sigma"), std::string::npos) << r.output;
  EXPECT_FALSE(std::ifstream(refused).good());
}

TEST(FitCli, ErrorsNameTheFile) {
  test::TempDir dir;
  const std::string coarse = dir.file("coarse.ply");
  ASSERT_EQ(run_command(gpsurf("sample icosphere --size 80 -o " + coarse)).exit_code, 0);
  const auto missing =
      run_command(gpsurf("fit " + coarse + " --target " + dir.file("none.obj") + " -o " + dir.file("o.ply")));
  EXPECT_NE(missing.exit_code, 0);
  EXPECT_NE(missing.output.find("none.obj"), std::string::npos) << missing.output;
  const auto no_target = run_command(gpsurf("fit " + coarse + " -o " + dir.file("o.ply")));
  EXPECT_NE(no_target.exit_code, 0);
  EXPECT_NE(no_target.output.find("--target"), std::string::npos) << no_target.output;
}

// An output the fit could not write is refused before it fits (it was after every iteration).
TEST(FitCli, AnOutputItCannotWriteIsRefusedBeforeTheFit) {
  test::TempDir dir;
  const std::string coarse = dir.file("coarse.ply"), dense = dir.file("dense.ply");
  ASSERT_EQ(run_command(gpsurf("sample icosphere --size 80 -o " + coarse)).exit_code, 0);
  ASSERT_EQ(run_command(gpsurf("sample sphere --size 2000 -o " + dense)).exit_code, 0);
  const std::string fit = "fit " + coarse + " --target " + dense + " -o ";
  const std::vector<std::tuple<std::string, int, std::string>> cases = {
      {dir.file("out.xyz"), 2, "out.xyz: cannot write format '.xyz'"},
      {dir.file("none/out.ply"), 1, "none/out.ply"},
      {dir.path().string(), 1, "directory"}};
  for (const auto& [output, code, said] : cases) {
    const auto r = run_command(gpsurf(fit + output));
    EXPECT_EQ(r.exit_code, code) << r.output;
    EXPECT_NE(r.output.find(said), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("iteration"), std::string::npos) << r.output;
  }
}

}  // namespace
}  // namespace gps
