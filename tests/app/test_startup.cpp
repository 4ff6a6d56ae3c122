// What gpsurf loads to start: the commands that need neither GL nor images (info, sample, subdivide,
// --help, ...) load no GL, windowing or image library, and `info` of a small mesh stays within 40 MB;
// the GL commands run in gpsurf-render with the same arguments, and without it gpsurf says so in
// one line.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/measured_run.h"
#include "tests/support/run_command.h"
#include "tests/support/sanitized_build.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

using test::gpsurf;
using test::run_command;

using test::MeasuredRun;

// Runs gpsurf with `args`, its output discarded; with `trace`, the libraries it loads are written there.
MeasuredRun run_gpsurf(const std::vector<std::string>& args, const std::string& trace = "") {
  std::vector<std::string> argv{GPSURF_BINARY};
  argv.insert(argv.end(), args.begin(), args.end());
  return test::run_measured(argv, trace);
}

// What the loader wrote for a run traced into `folder`/trace.
std::string loaded_libraries(const std::filesystem::path& folder) {
  std::string text;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    std::ifstream in(entry.path());
    std::stringstream s;
    s << in.rdbuf();
    text += s.str();
  }
  return text;
}

// The libraries of GL, windows and images that the CPU commands must not load.
const char* const kGlAndImageLibraries[] = {"libGL.", "libGLX", "libEGL", "libOSMesa", "libglfw",
                                            "libOpenImageIO", "libOpenEXR", "libIlmImf", "libX11"};

bool lists_gl_commands() { return run_command(gpsurf("--help")).output.find("\n  render ") != std::string::npos; }

class Startup : public ::testing::Test {
protected:
  void SetUp() override {
    mesh_ = dir_.file("cone.ply");
    ASSERT_EQ(run_command(gpsurf("sample cone-pointy -o " + mesh_)).exit_code, 0);
  }
  // The libraries a traced run of gpsurf `args` loaded; fails the test where it exits otherwise than 0.
  std::string traced(const std::vector<std::string>& args, const std::string& name) {
    const std::filesystem::path folder = dir_.path() / name;
    std::filesystem::create_directories(folder);
    const MeasuredRun run = run_gpsurf(args, (folder / "trace").string());
    EXPECT_EQ(run.exit_code, 0) << name;
    return loaded_libraries(folder);
  }
  test::TempDir dir_;
  std::string mesh_;
};

TEST_F(Startup, CpuCommandsLoadNeitherGlNorImages) {
  const std::string output = dir_.file("out.ply");
  const std::vector<std::pair<std::string, std::vector<std::string>>> runs = {
      {"info", {"info", mesh_}},
      {"help", {"--help"}},
      {"subdivide", {"subdivide", mesh_, "-o", output, "--levels", "1"}},
      {"tessellate", {"tessellate", mesh_, "-o", output, "--level", "2"}},
  };
  for (const auto& [name, args] : runs) {
    const std::string libraries = traced(args, name);
    // The trace works: it names the C++ library every run loads.
    ASSERT_NE(libraries.find("libstdc++"), std::string::npos) << name << ": no loader trace";
    for (const char* library : kGlAndImageLibraries)
      EXPECT_EQ(libraries.find(library), std::string::npos) << name << " loaded " << library;
  }
}

TEST_F(Startup, TheTraceSeesGlWhereARenderCommandLoadsIt) {
  if (!lists_gl_commands()) GTEST_SKIP() << "built without GL";
  const std::string libraries = traced({"render", "--help"}, "render");
  EXPECT_NE(libraries.find("libEGL"), std::string::npos);
}

// A render to PNG writes through libpng; OpenImageIO (some 260 libraries) is opened only for a
// format besides PNG, here the position AOV's EXR, through gpsurf's image module.
TEST_F(Startup, OpenImageIOIsLoadedOnlyForFormatsBesidesPng) {
  if (!lists_gl_commands()) GTEST_SKIP() << "built without GL";
  const std::string png = dir_.file("cone.png"), exr = dir_.file("cone.exr");
  const std::string plain = traced({"render", mesh_, "-o", png, "--size", "64x48"}, "png");
  EXPECT_NE(plain.find("libpng"), std::string::npos);
  EXPECT_EQ(plain.find("libOpenImageIO"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(png));
  const std::string aov = traced({"render", mesh_, "-o", png, "--size", "64x48", "--aov", "position=" + exr}, "exr");
  EXPECT_NE(aov.find("libgpsurf_openimageio"), std::string::npos);
  EXPECT_NE(aov.find("libOpenImageIO"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(exr));
}

TEST_F(Startup, InfoOfASmallMeshStaysWithinFortyMegabytes) {
#ifdef GPS_SANITIZED
  GTEST_SKIP() << "the sanitizers' shadow memory is no measure of gpsurf's";
#endif
  for (const std::vector<std::string>& args : {std::vector<std::string>{"info", mesh_}, {"--help"}, {"--version"}}) {
    const MeasuredRun run = run_gpsurf(args);
    EXPECT_EQ(run.exit_code, 0) << args.front();
    EXPECT_LT(run.peak_kb, 40 * 1024) << args.front();
  }
}

TEST_F(Startup, GlCommandsRunInTheirProgramWithTheSameArguments) {
  if (!lists_gl_commands()) GTEST_SKIP() << "built without GL";
  const auto help = run_command(gpsurf("render --help"));
  EXPECT_EQ(help.exit_code, 0) << help.output;
  EXPECT_NE(help.output.find("--script"), std::string::npos) << help.output;
  // A usage error of render's own options keeps its exit code and gpsurf's prefix.
  const auto wrong = run_command(gpsurf("render " + mesh_ + " -o " + dir_.file("x.png") + " --size 0x0"));
  EXPECT_EQ(wrong.exit_code, 2) << wrong.output;
  EXPECT_EQ(wrong.output.rfind("gpsurf: ", 0), 0u) << wrong.output;
}

TEST_F(Startup, AGlCommandWithoutItsProgramIsOneLineAndExitOne) {
  // A copy of gpsurf alone in a folder: gpsurf-render is neither beside it nor where it installs.
  const std::filesystem::path alone = dir_.path() / "bin" / "gpsurf";
  std::filesystem::create_directories(alone.parent_path());
  std::filesystem::copy_file(GPSURF_BINARY, alone);
  for (const char* command : {"render", "bench", "diff"}) {
    const auto r = run_command(alone.string() + " " + command + " " + mesh_);
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_EQ(r.output.rfind(std::string("gpsurf: ") + command + " ", 0), 0u) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  }
}

}  // namespace
}  // namespace gps
