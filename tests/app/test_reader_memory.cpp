// Readers never hold much more than the file's own size: inputs built to make a reader
// allocate from a header count (faces of 0 vertices, a vertex element of blank space, an OFF header
// with huge counts) are refused with peak memory within 4× the file size over gpsurf's own baseline.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <string>

#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

struct MeasuredRun {
  int exit_code = -1;
  long peak_kb = 0;  // the child's maximum resident set size
};

MeasuredRun run_measured(const std::vector<std::string>& args) {
  std::fflush(stdout);  // or the child would print what is buffered again
  const pid_t child = ::fork();
  if (child == 0) {
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::freopen("/dev/null", "w", stdout);
    ::freopen("/dev/null", "w", stderr);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  int status = 0;
  rusage usage{};
  ::wait4(child, &status, 0, &usage);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, usage.ru_maxrss};
}

constexpr size_t kSize = 16 << 20;  // 16 MiB inputs

TEST(ReaderMemory, AmplificationInputsAreRefusedWithinFourTimesTheFileSize) {
  test::TempDir dir;
  const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
  const std::vector<std::pair<std::string, std::string>> inputs = {
      // Binary faces of 0 vertices: one byte each, 24+ bytes each if sized from the header.
      {"zero_faces.ply",
       "ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
       "property float z\nelement face " +
           std::to_string(kSize) + "\nproperty list uchar int vertex_indices\nend_header\n" + std::string(kSize, '\0')},
      // A vertex element of blank space: counts allowed by the size, no values.
      {"blank_vertices.ply", "ply\nformat ascii 1.0\nelement vertex " + std::to_string(kSize / 6) +
                                 "\nproperty double x\nproperty double y\nproperty double z\nend_header\n" +
                                 std::string(kSize, ' ')},
      {"blank_lines.ply", "ply\nformat ascii 1.0\nelement vertex " + std::to_string(kSize / 6) +
                              "\nproperty double x\nproperty double y\nproperty double z\nend_header\n" +
                              std::string(kSize, '\n')},
      {"huge_counts.off", "OFF\n" + std::to_string(kSize / 6) + " " + std::to_string(kSize / 8) + " 0\n" + vertices +
                              std::string(kSize, ' ')},
      {"many_short_faces.off", "OFF\n3 " + std::to_string(kSize / 8) + " 0\n" + vertices + std::string(kSize, '\n')},
  };
  const MeasuredRun baseline = run_measured({GPSURF_BINARY, "sample", "--list"});
  ASSERT_EQ(baseline.exit_code, 0);
  for (const auto& [name, contents] : inputs) {
    const std::string path = dir.write(name, contents);
    const MeasuredRun r = run_measured({GPSURF_BINARY, "info", path});
    const long bound_kb = baseline.peak_kb + long(4 * contents.size() / 1024);
    std::printf("%-22s %6zu KiB file: exit %d, peak %ld KiB (baseline %ld KiB, %.2fx the file over it)\n", name.c_str(),
                contents.size() / 1024, r.exit_code, r.peak_kb, baseline.peak_kb,
                double(r.peak_kb - baseline.peak_kb) * 1024.0 / double(contents.size()));
    EXPECT_EQ(r.exit_code, 1) << name;
    EXPECT_LT(r.peak_kb, bound_kb) << name;
    std::filesystem::remove(path);
  }
}

}  // namespace
}  // namespace gps
