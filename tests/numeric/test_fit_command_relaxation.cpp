// gpsurf fit relaxing its standard deviations' lower bound once converged, as a user reads it: the
// line that says so, and one stage only where the relaxed bound is the first. Two whole fits, slow
// instrumented: the relaxation's logic is checked in the sanitizer build by tests/core/test_limit_fit.cpp,
// and the option's refusal by tests/app/test_fit_command.cpp.
#include <gtest/gtest.h>

#include <string>

#include "core/io/text_file.h"
#include "tests/support/run_command.h"
#include "tests/support/sphere_points.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

using test::gpsurf;
using test::run_command;

TEST(FitCli, SaysWhenItRelaxesTheLowerBoundAndOneStageIsAsked) {
  test::TempDir dir;
  const std::string target = dir.write("target.obj", test::sphere_obj(8, 0.3));  // an ellipsoid 0.3 as thick as wide
  const std::string coarse = dir.file("coarse.ply"), two = dir.file("two.ply"), one = dir.file("one.ply");
  ASSERT_EQ(run_command(gpsurf("sample icosphere --size 80 -o " + coarse)).exit_code, 0);
  const std::string fit = "fit " + coarse + " --target " + target + " --level 0 -o ";
  const auto relaxed = run_command(gpsurf(fit + two));
  ASSERT_EQ(relaxed.exit_code, 0) << relaxed.output;
  EXPECT_NE(relaxed.output.find("the standard deviations' lower bound relaxed from 0.35 to 0.1 of their vertex's mean "
                                "edge length\niteration "),
            std::string::npos)
      << relaxed.output;
  const auto once = run_command(gpsurf(fit + one + " --relaxed-min-sigma 0.35"));
  ASSERT_EQ(once.exit_code, 0) << once.output;
  EXPECT_EQ(once.output.find("relaxed"), std::string::npos) << once.output;
  EXPECT_NE(read_text_file(one), read_text_file(two));
}

}  // namespace
}  // namespace gps
