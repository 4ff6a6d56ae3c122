// A soak of hostile inputs, each generated here at up to 16 MiB and run through the built gpsurf as a
// user would: every one is read or refused with its exit code within 2 s of processor time (crowds of
// coincident vertices, PLY headers of many properties or elements, a face of many coincident corners,
// which took time quadratic in their size), and the large ones (a face repeated, one long triangle
// strip, grids) within 8 times the file's size of memory over gpsurf's own baseline; and a render of a
// surface in view draws it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "render/image/image_io.h"
#include "tests/support/run_command.h"
#include "tests/support/sanitized_build.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

using test::gpsurf;
using test::run_command;

constexpr size_t kSize = 16 << 20;  // the largest inputs

struct Measured {
  int exit_code = -1;
  long peak_kb = 0;
  double cpu_seconds = 0;
};

// `gpsurf ARGS` run under GNU time, its output discarded: a child of this test process would count
// the test's own pages, which a fork copies, in its peak; time's child starts small.
Measured run_timed(const std::string& args, const std::string& report) {
  const test::CommandResult r =
      run_command("/usr/bin/time -f '%x %M %U %S' -o " + report + " " + gpsurf(args) + " > /dev/null 2>&1");
  std::ifstream in(report);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  Measured m;
  double user = 0, system = 0;
  std::istringstream(last) >> m.exit_code >> m.peak_kb >> user >> system;
  m.cpu_seconds = user + system;
  EXPECT_EQ(r.exit_code, m.exit_code) << args << ": " << last;
  return m;
}

struct Probe {
  std::string file;     // written by `write`
  std::string command;  // run on it, with the output (where any) in the test folder
  int exit_code;
  // The peak memory allowed over the baseline, in file sizes: 8 for the large inputs; the small ones,
  // whose 8-byte vertex records each become a vertex of the mesh (its covariance and half-edge
  // records, some 150 bytes), are bounded only against a reader or diagnosis that grows past linear.
  double memory_bound;
  std::function<void(std::ostream&)> write;
};
constexpr double kSmall = 24, kLarge = 8;

// A cube's OBJ lines (vertices 1–8).
void write_obj_cube(std::ostream& out) {
  out << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
      << "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
}

// An n × n grid of quads, its vertices numbered from `base` (OBJ 1, OFF 0).
template <class Vertex, class Face>
void write_grid(int n, const Vertex& vertex, const Face& face) {
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) vertex(i, j);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) face(i * (n + 1) + j, (i + 1) * (n + 1) + j);
}

std::vector<Probe> probes() {
  std::vector<Probe> out;
  // 120,000 vertices at one point, in 40,000 triangles: refused (no area) after the weld finds them.
  const auto crowd = [](std::ostream& o) {
    for (int i = 0; i < 120000; ++i) o << "v 0 0 0\n";
    for (int i = 0; i < 120000; i += 3) o << "f " << i + 1 << ' ' << i + 2 << ' ' << i + 3 << '\n';
  };
  out.push_back({"crowd.obj", "info", 1, kSmall, crowd});
  out.push_back({"crowd.obj", "tessellate --level 1 -o out.ply", 1, kSmall, crowd});
  // A cube and 120,000 vertices in no face at one point: read, the isolated vertices listed.
  out.push_back({"unused.obj", "info", 0, kSmall, [](std::ostream& o) {
                   write_obj_cube(o);
                   for (int i = 0; i < 120000; ++i) o << "v 5 5 5\n";
                 }});
  // PLY headers of 40,000 properties (refused: no x) and of 40,000 empty elements (read).
  out.push_back({"properties.ply", "info", 1, kSmall, [](std::ostream& o) {
                   o << "ply\nformat ascii 1.0\nelement vertex 3\n";
                   for (int i = 0; i < 40000; ++i) o << "property float p" << i << '\n';
                   o << "end_header\n";
                 }});
  out.push_back({"elements.ply", "info", 0, kSmall, [](std::ostream& o) {
                   o << "ply\nformat ascii 1.0\n";
                   for (int i = 0; i < 40000; ++i) o << "element e" << i << " 0\n";
                   o << "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                     << "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
                     << "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
                 }});
  // One OFF face of 160,000 corners, every vertex at one point: refused.
  out.push_back({"long_face.off", "info", 1, kSmall, [](std::ostream& o) {
                   const int n = 160000;
                   o << "OFF\n" << n << " 1 0\n";
                   for (int i = 0; i < n; ++i) o << "0 0 0\n";
                   o << n;
                   for (int i = 0; i < n; ++i) o << ' ' << i;
                   o << '\n';
                 }});
  // 16 MiB of one face repeated: refused (duplicates).
  out.push_back(
      {"repeated_face.ply", "info", 1, kLarge, [](std::ostream& o) {
         const size_t n = kSize / 8 - 64;  // with the header, within kSize
         o << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
           << "element face " << n << "\nproperty list uchar int vertex_indices\nend_header\n"
           << "0 0 0\n1 0 0\n0 1 0\n";
         for (size_t i = 0; i < n; ++i) o << "3 0 1 2\n";
       }});
  // One binary triangle strip of 4M indices around 4 vertices: a triangle per index, refused.
  out.push_back({"one_strip.ply", "info", 1, kLarge, [](std::ostream& o) {
                   const uint32_t n = kSize / 4 - 64;
                   o << "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                     << "property float z\nelement tristrips 1\nproperty list uint int vertex_indices\nend_header\n";
                   const float xyz[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
                   o.write(reinterpret_cast<const char*>(xyz), sizeof xyz);
                   o.write(reinterpret_cast<const char*>(&n), 4);
                   std::vector<int32_t> indices(n);
                   for (uint32_t i = 0; i < n; ++i) indices[i] = int32_t(i % 4);
                   o.write(reinterpret_cast<const char*>(indices.data()), std::streamsize(4 * size_t(n)));
                 }});
  // An op list of about 16 MB: 350,000 edits of Gaussians, made on the cube (the file is the list; {file}
  // stands for it). Each step held as its one kind of action, not three (8.5 times the file before).
  out.push_back({"ops.json", "edit sample:cube -o out.ply --quiet --ops @{file}", 0, kLarge, [](std::ostream& o) {
                   o << '[';
                   for (int i = 0; i < 350000; ++i)
                     o << (i ? "," : "") << R"({"op":"set","vertices":[)" << i % 8 << R"(],"scale":1.0})";
                   o << ']';
                 }});
  // Grids of quads of about 16 MB: read.
  constexpr int kGrid = 620;
  out.push_back(
      {"grid.obj", "info", 0, kLarge, [](std::ostream& o) {
         write_grid(
             kGrid, [&](int i, int j) { o << "v " << i << ' ' << j << " 0\n"; },
             [&](int a, int b) { o << "f " << a + 1 << ' ' << b + 1 << ' ' << b + 2 << ' ' << a + 2 << '\n'; });
       }});
  out.push_back({"grid.off", "info", 0, kLarge, [](std::ostream& o) {
                   o << "OFF\n" << (kGrid + 1) * (kGrid + 1) << ' ' << kGrid * kGrid << " 0\n";
                   write_grid(
                       kGrid, [&](int i, int j) { o << i << ' ' << j << " 0\n"; },
                       [&](int a, int b) { o << "4 " << a << ' ' << b << ' ' << b + 1 << ' ' << a + 1 << '\n'; });
                 }});
  return out;
}

TEST(HostileInputSoak, EveryInputIsReadOrRefusedWithinTwoSecondsAndItsMemoryBound) {
#if defined(GPS_SANITIZED)
  GTEST_SKIP() << "AddressSanitizer's redzones and quarantine hold more than gpsurf does; the bounds are the plain "
                  "build's";
#endif
  ASSERT_TRUE(std::filesystem::exists("/usr/bin/time")) << "GNU time is needed (scripts/install_deps.sh)";
  test::TempDir dir;
  const std::string report = dir.file("time.txt");
  const Measured baseline = run_timed("sample --list", report);
  ASSERT_EQ(baseline.exit_code, 0);
  for (const Probe& probe : probes()) {
    const std::string path = dir.file(probe.file);
    if (!std::filesystem::exists(path)) {
      std::ofstream out(path, std::ios::binary);
      probe.write(out);
    }
    const size_t size = std::filesystem::file_size(path);
    ASSERT_LE(size, kSize) << probe.file;
    // The file after the command's name, or where the command says {file}; out.ply in the test folder.
    std::string command = probe.command;
    if (const size_t at = command.find("{file}"); at != std::string::npos)
      command.replace(at, 6, path);
    else
      command.insert(std::min(command.find(' '), command.size()), " " + path);
    if (const size_t at = command.find("out.ply"); at != std::string::npos) command.replace(at, 7, dir.file("out.ply"));
    const Measured r = run_timed(command, report);
    const std::string what = probe.file + " (" + probe.command + ")";
    std::printf("%-42s %6zu KiB: exit %d, %.2f s, peak %ld KiB (%.2fx the file over the baseline)\n", what.c_str(),
                size / 1024, r.exit_code, r.cpu_seconds, r.peak_kb,
                double(r.peak_kb - baseline.peak_kb) * 1024.0 / double(size));
    EXPECT_EQ(r.exit_code, probe.exit_code) << what;
    EXPECT_LT(r.cpu_seconds, 2.0) << what;
    EXPECT_LT(double(r.peak_kb), double(baseline.peak_kb) + probe.memory_bound * double(size) / 1024) << what;
  }
}

// The fraction of an image's pixels that differ from its corner's (the background).
double drawn_fraction(const Image& image) {
  long drawn = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c)
        if (std::abs(image.at(x, y, c) - image.at(0, 0, c)) > 0.05f) {
          ++drawn;
          break;
        }
  return double(drawn) / double(image.width * image.height);
}

// A surface in view is drawn: a sample, and an OBJ cube whose faces each have their own corners (read
// through --repair's weld).
TEST(HostileInputSoak, ARenderOfASurfaceInViewDrawsIt) {
  test::TempDir dir;
  ASSERT_EQ(run_command(gpsurf("sample torus -o " + dir.file("torus.ply"))).exit_code, 0);
  {
    std::ofstream out(dir.file("cube.obj"));
    const char* positions[8] = {"0 0 0", "1 0 0", "1 1 0", "0 1 0", "0 0 1", "1 0 1", "1 1 1", "0 1 1"};
    const int corners[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    int next = 1;
    for (const auto& face : corners) {
      for (const int v : face) out << "v " << positions[v] << '\n';
      out << "f " << next << ' ' << next + 1 << ' ' << next + 2 << ' ' << next + 3 << '\n';
      next += 4;
    }
  }
  for (const std::string input : {"torus.ply --size 160x120", "cube.obj --repair --size 160x120"}) {
    const auto r = run_command(gpsurf("render " + dir.file(input.substr(0, input.find(' '))) + " -o " +
                                      dir.file("out.png") + input.substr(input.find(' '))));
    ASSERT_EQ(r.exit_code, 0) << input << ": " << r.output;
    EXPECT_GT(drawn_fraction(read_image(dir.file("out.png"))), 0.1) << input;
  }
}

}  // namespace
}  // namespace gps
