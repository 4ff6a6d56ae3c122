// Readers never hold much more than the file's own size: inputs built to make a reader
// allocate from a header count (faces of 0 vertices, a vertex element of blank space, an OFF header
// with huge counts) are refused with peak memory within 4× the file size over gpsurf's own baseline;
// inputs whose records are short beside what they become in memory (vertices without faces, a face
// repeated, one long face, many small disconnected triangles) are read within 8× the file size.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "core/io/mesh_io.h"
#include "core/support/error.h"

#include "tests/support/measured_run.h"
#include "tests/support/run_command.h"
#include "tests/support/sanitized_build.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

using test::MeasuredRun;
using test::run_measured;

// The peak resident set of a forked child running `f` (its exit code: 0, or 1 where f throws
// gps::Error). The child starts with this process's pages, so a child that does nothing is the baseline.
MeasuredRun run_forked(const std::function<void()>& f) {
  std::fflush(stdout);
  const pid_t child = ::fork();
  if (child == 0) {
    int code = 0;
    try {
      f();
    } catch (const Error&) {
      code = 1;
    }
    ::_exit(code);
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
  // A header and kSize bytes of one kind, written in pieces: the children of this process start from
  // its resident pages, which must not hold the inputs.
  struct Input {
    std::string name, head;
    char fill;
  };
  const std::vector<Input> inputs = {
      // Binary faces of 0 vertices: one byte each, 24+ bytes each if sized from the header.
      {"zero_faces.ply",
       "ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
       "property float z\nelement face " +
           std::to_string(kSize) + "\nproperty list uchar int vertex_indices\nend_header\n",
       '\0'},
      // A vertex element of blank space: counts allowed by the size, no values.
      {"blank_vertices.ply",
       "ply\nformat ascii 1.0\nelement vertex " + std::to_string(kSize / 6) +
           "\nproperty double x\nproperty double y\nproperty double z\nend_header\n",
       ' '},
      {"blank_lines.ply",
       "ply\nformat ascii 1.0\nelement vertex " + std::to_string(kSize / 6) +
           "\nproperty double x\nproperty double y\nproperty double z\nend_header\n",
       '\n'},
      {"huge_counts.off", "OFF\n" + std::to_string(kSize / 6) + " " + std::to_string(kSize / 8) + " 0\n" + vertices,
       ' '},
      {"many_short_faces.off", "OFF\n3 " + std::to_string(kSize / 8) + " 0\n" + vertices, '\n'},
  };
  const MeasuredRun baseline = run_measured({GPSURF_BINARY, "sample", "--list"});
  ASSERT_EQ(baseline.exit_code, 0);
  for (const auto& [name, head, fill] : inputs) {
    const std::string path = dir.file(name);
    {
      std::ofstream out(path, std::ios::binary);
      out << head;
      const std::string piece(1 << 16, fill);
      for (size_t written = 0; written < kSize; written += piece.size()) out << piece;
    }
    const size_t size = std::filesystem::file_size(path);
    const MeasuredRun r = run_measured({GPSURF_BINARY, "info", path});
    const long bound_kb = baseline.peak_kb + long(4 * size / 1024);
    std::printf("%-22s %6zu KiB file: exit %d, peak %ld KiB (baseline %ld KiB, %.2fx the file over it)\n", name.c_str(),
                size / 1024, r.exit_code, r.peak_kb, baseline.peak_kb,
                double(r.peak_kb - baseline.peak_kb) * 1024.0 / double(size));
    EXPECT_EQ(r.exit_code, 1) << name;
    EXPECT_LT(r.peak_kb, bound_kb) << name;
    std::filesystem::remove(path);
  }
}

TEST(ReaderMemory, AmplificationInputsAreReadWithinEightTimesTheFileSize) {
#if defined(GPS_SANITIZED)
  GTEST_SKIP() << "AddressSanitizer's redzones and quarantine hold more than the readers do; the bound is the "
                  "plain build's";
#endif
  test::TempDir dir;
  struct Input {
    std::string name;
    int exit_code;
  };
  std::vector<Input> inputs;
  // Written a line at a time: this process holds none of it, so its children's baseline is its own.
  const auto add = [&](const std::string& name, int exit_code, const std::function<void(std::ostream&)>& write) {
    std::ofstream out(dir.file(name), std::ios::binary);
    write(out);
    inputs.push_back({name, exit_code});
  };
  add("vertices_only.obj", 1, [](std::ostream& out) {
    for (size_t i = 0; i < kSize / 8; ++i) out << "v 0 0 0\n";
  });
  add("repeated_face.obj", 1, [](std::ostream& out) {
    out << "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (size_t i = 0; i < kSize / 8; ++i) out << "f 1 2 3\n";
  });
  add("long_face.obj", 1, [](std::ostream& out) {
    out << "v 0 0 0\nf";
    for (size_t i = 0; i < kSize / 2; ++i) out << " 1";
    out << '\n';
  });
  // Disconnected triangles: three short vertex records and a face each. The mesh itself holds a
  // covariance and the connectivity's vertex, edge and face records per vertex, which files of much shorter
  // vertex records than these would exceed 8 times over whatever the reader did.
  add("triangles.obj", 0, [](std::ostream& out) {
    const int n = 150000;
    for (int i = 0; i < n; ++i) out << "v " << i << " 0 0\nv " << i << " 1 0\nv " << i << " 0 1\n";
    for (int i = 0; i < n; ++i) out << "f " << 3 * i + 1 << ' ' << 3 * i + 2 << ' ' << 3 * i + 3 << '\n';
  });
  add("triangles.off", 0, [](std::ostream& out) {
    const int n = 150000;
    out << "OFF\n" << 3 * n << ' ' << n << " 0\n";
    for (int i = 0; i < n; ++i) out << i << ".5 0 0\n" << i << ".5 1 0\n" << i << ".5 0 1\n";
    for (int i = 0; i < n; ++i) out << "3 " << 3 * i << ' ' << 3 * i + 1 << ' ' << 3 * i + 2 << '\n';
  });
  add("triangles.ply", 0, [](std::ostream& out) {
    const int n = 150000;
    out << "ply\nformat ascii 1.0\nelement vertex " << 3 * n
        << "\nproperty double x\nproperty double y\nproperty double z\nelement face " << n
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (int i = 0; i < n; ++i) out << i << ".5 0 0\n" << i << ".5 1 0\n" << i << ".5 0 1\n";
    for (int i = 0; i < n; ++i) out << "3 " << 3 * i << ' ' << 3 * i + 1 << ' ' << 3 * i + 2 << '\n';
  });
  const MeasuredRun baseline = run_forked([] {});
  ASSERT_EQ(baseline.exit_code, 0);
  for (const Input& input : inputs) {
    const std::string path = dir.file(input.name);
    const size_t size = std::filesystem::file_size(path);
    const MeasuredRun r = run_forked([&] { (void)read_mesh(path); });
    std::printf("%-18s %6zu KiB file: exit %d, peak %ld KiB (baseline %ld KiB, %.2fx the file over it)\n",
                input.name.c_str(), size / 1024, r.exit_code, r.peak_kb, baseline.peak_kb,
                double(r.peak_kb - baseline.peak_kb) * 1024.0 / double(size));
    EXPECT_EQ(r.exit_code, input.exit_code) << input.name;
    EXPECT_LT(r.peak_kb, baseline.peak_kb + long(8 * size / 1024)) << input.name;
  }
}

}  // namespace
}  // namespace gps
