// The long commands' progress bar as a user sees it: drawn on stderr when it is a terminal (run here
// through a pseudo-terminal by util-linux's `script`), absent under --quiet and where stderr is a pipe
// or a file, so that what scripts capture stays as it was.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

using test::gpsurf;
using test::run_command;

bool has_script() { return run_command("command -v script").exit_code == 0; }

// `args` run by gpsurf on a pseudo-terminal: its stdout and stderr together as the terminal got them.
test::CommandResult on_terminal(const std::string& args) {
  return run_command("script -qec '" + gpsurf(args) + "' /dev/null");
}

// `args` run by gpsurf with stderr to a file: its stdout, and the file's text in `error`.
test::CommandResult with_stderr_to_file(const test::TempDir& dir, const std::string& args, std::string& error) {
  const std::string path = dir.file("stderr.txt");
  const auto r = run_command("(" + gpsurf(args) + " 2>" + path + ")");
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  error = text.str();
  return r;
}

int count(const std::string& text, const std::string& part) {
  int n = 0;
  for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

TEST(ProgressCli, SimplifyDrawsABarOnATerminalOnly) {
  if (!has_script()) GTEST_SKIP() << "no `script` to run a pseudo-terminal";
  test::TempDir dir;
  ASSERT_EQ(run_command(gpsurf("sample icosphere --size 1280 -o " + dir.file("ico.ply"))).exit_code, 0);
  const std::string args = "simplify " + dir.file("ico.ply") + " -o " + dir.file("c.ply") + " --vertices 100";
  const auto shown = on_terminal(args);
  ASSERT_EQ(shown.exit_code, 0) << shown.output;
  EXPECT_NE(shown.output.find("\rsimplifying [                              ]   0%"), std::string::npos)
      << shown.output;
  // The last drawing at 100%, its line ended before the report.
  EXPECT_NE(shown.output.find("\rsimplifying [##############################] 100%"), std::string::npos)
      << shown.output;
  EXPECT_LT(shown.output.rfind("100%"), shown.output.find("simplified 642 vertices"));

  const auto quiet = on_terminal(args + " --quiet");
  ASSERT_EQ(quiet.exit_code, 0) << quiet.output;
  EXPECT_EQ(quiet.output, "");

  std::string error;
  const auto piped = with_stderr_to_file(dir, args, error);
  ASSERT_EQ(piped.exit_code, 0) << piped.output;
  EXPECT_EQ(error, "");
  EXPECT_NE(piped.output.find("simplified 642 vertices"), std::string::npos) << piped.output;
  EXPECT_EQ(count(piped.output, "simplifying"), 0);
}

TEST(ProgressCli, FitDrawsABarBetweenItsIterationLines) {
  if (!has_script()) GTEST_SKIP() << "no `script` to run a pseudo-terminal";
  test::TempDir dir;
  ASSERT_EQ(run_command(gpsurf("sample icosphere --size 1280 -o " + dir.file("ico.ply"))).exit_code, 0);
  ASSERT_EQ(run_command(gpsurf("simplify " + dir.file("ico.ply") + " -o " + dir.file("c.ply") +
                               " --vertices 100 --level 0"))
                .exit_code,
            0);
  const std::string args =
      "fit " + dir.file("c.ply") + " --target " + dir.file("ico.ply") + " -o " + dir.file("f.ply") + " --iterations 2";
  const auto shown = on_terminal(args);
  ASSERT_EQ(shown.exit_code, 0) << shown.output;
  // Each iteration's line takes the bar's place, blanked, and the bar is drawn again below it.
  EXPECT_NE(shown.output.find("\rfitting [                              ]   0%"), std::string::npos) << shown.output;
  EXPECT_NE(shown.output.find("\rfitting [###############               ]  50%"), std::string::npos) << shown.output;
  const size_t half = shown.output.find("]  50%");
  EXPECT_LT(shown.output.find("iteration 1:"), half);
  EXPECT_GT(shown.output.find("iteration 2:"), half);
  EXPECT_GT(shown.output.find("] 100%"), shown.output.find("iteration 2:"));
  EXPECT_EQ(count(shown.output, "iteration "), 3) << shown.output;

  const auto quiet = on_terminal(args + " -q");
  ASSERT_EQ(quiet.exit_code, 0) << quiet.output;
  EXPECT_EQ(quiet.output, "");

  std::string error;
  const auto piped = with_stderr_to_file(dir, args, error);
  ASSERT_EQ(piped.exit_code, 0) << piped.output;
  EXPECT_EQ(error, "");
  EXPECT_EQ(count(piped.output, "iteration "), 3) << piped.output;
}

TEST(ProgressCli, RepairAndTessellateDrawTheirBars) {
  if (!has_script()) GTEST_SKIP() << "no `script` to run a pseudo-terminal";
  test::TempDir dir;
  // Two triangles of a square, each with its own corners: --repair welds the diagonal's.
  const std::string soup = dir.write("soup.obj",
                                     "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 4 5 6\n");
  const std::string args = "tessellate " + soup + " -o " + dir.file("t.ply") + " --level 2 --repair";
  const auto shown = on_terminal(args);
  ASSERT_EQ(shown.exit_code, 0) << shown.output;
  EXPECT_NE(shown.output.find("\rrepairing [                              ]   0%"), std::string::npos) << shown.output;
  const size_t done = shown.output.find("\rrepairing [##############################] 100%");
  ASSERT_NE(done, std::string::npos) << shown.output;
  const size_t report = shown.output.find("repair: welded 4 coincident vertices into 2");
  ASSERT_NE(report, std::string::npos) << shown.output;
  EXPECT_GT(report, done);
  const size_t tessellated = shown.output.find("\rtessellating [##############################] 100%");
  ASSERT_NE(tessellated, std::string::npos) << shown.output;
  EXPECT_GT(tessellated, report);
  EXPECT_EQ(on_terminal(args + " --quiet").output, "");

  std::string error;
  const auto piped = with_stderr_to_file(dir, args, error);
  ASSERT_EQ(piped.exit_code, 0) << piped.output;
  EXPECT_EQ(error, "");
  EXPECT_EQ(count(piped.output, "repairing") + count(piped.output, "tessellating"), 0) << piped.output;
  EXPECT_NE(piped.output.find("repair: welded 4 coincident vertices into 2\n"), std::string::npos) << piped.output;
}

}  // namespace
}  // namespace gps
