// A program of ours that dies of a fatal signal where GPSURF_CRASH_STACK is set writes the signal and
// its stack, its own frames named, then dies of it as before (app/crash_stack.h); where it is not set,
// it writes nothing of the kind.
#include <gtest/gtest.h>

#include <string>

#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

using test::gpsurf;
using test::run_command;

// gpsurf making a sample of a million faces (seconds of work, more in a sanitized build), sent SIGSEGV
// after a second, with `environment` before it. --foreground: the signal goes to the program once,
// where the kernel gives it to the main thread, not again to its process group.
test::CommandResult segfaulted_run(const test::TempDir& dir, const std::string& environment) {
  return run_command(environment + " timeout --foreground --preserve-status -s SEGV 1 " +
                     gpsurf("sample sphere --size 1000000 -o " + dir.file("sphere.ply")));
}

TEST(CrashStack, AFatalSignalWritesTheStackWhereAsked) {
  test::TempDir dir;
  const test::CommandResult r = segfaulted_run(dir, "GPSURF_CRASH_STACK=1");
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("gpsurf: fatal signal 11 (SIGSEGV); its stack, innermost first:\n"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("its own frames, named:\n"), std::string::npos) << r.output;
  // addr2line names the program's frames: main's among them, below the sample command's.
  EXPECT_NE(r.output.find("\nmain at "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("add_sample_command"), std::string::npos) << r.output;
}

TEST(CrashStack, NothingIsWrittenUnlessAsked) {
  test::TempDir dir;
  const test::CommandResult r = segfaulted_run(dir, "GPSURF_CRASH_STACK=");
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("fatal signal"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace gps
