// Only regular files are read, never past their size, and a file whose first bytes cannot begin its
// format is refused before the rest is read: FIFOs and devices at once (no hang), a sparse file of
// gigabytes without reading it, each with one line naming the file and what it is.
#include "core/io/text_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "core/io/mesh_io.h"
#include "core/support/error.h"
#include "tests/support/temp_dir.h"
#include "tests/support/error_of.h"

namespace gps {
namespace {

using test::error_of;

// A line of /proc/self/status ("VmRSS:", "VmHWM:") in MiB.
double status_mib(const std::string& key) {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind(key, 0) == 0) return std::stod(line.substr(key.size())) / 1024.0;
  ADD_FAILURE() << "no " << key << " in /proc/self/status";
  return 0.0;
}

// How far the process's resident memory rose above where it was while `run` ran, in MiB: the peak is
// reset first (/proc/self/clear_refs), so that the tests run before it in the same process do not count.
double peak_growth_mib(const std::function<void()>& run) {
  std::ofstream("/proc/self/clear_refs") << "5";
  const double before = status_mib("VmRSS:");
  run();
  return status_mib("VmHWM:") - before;
}

TEST(TextFile, AFifoIsRefusedByItsTypeWithoutWaitingForAWriter) {
  const test::TempDir dir;
  const std::string fifo = dir.file("pipe.ply");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(error_of([&] { read_mesh(fifo); }), fifo + ": is a FIFO (named pipe), not a file");
}

TEST(TextFile, DevicesAndFoldersAreRefusedByTheirType) {
  const test::TempDir dir;
  const std::string zero = dir.file("zero.ply");
  std::filesystem::create_symlink("/dev/zero", zero);
  EXPECT_EQ(error_of([&] { read_mesh(zero); }), zero + ": is a character device, not a file");
  std::filesystem::create_directory(dir.file("folder.obj"));
  EXPECT_EQ(error_of([&] { read_mesh(dir.file("folder.obj")); }),
            dir.file("folder.obj") + ": is a directory, not a file");
  EXPECT_EQ(error_of([&] { read_mesh(dir.file("missing.off")); }), dir.file("missing.off") + ": no such file");
  const std::string loop = dir.file("loop.stl");
  std::filesystem::create_symlink(loop, loop);
  EXPECT_EQ(error_of([&] { read_mesh(loop); }), loop + ": a loop of symbolic links");
}

// A sparse file of 2 GiB of zeros under each format's name: refused from its first bytes, without
// the gigabytes read or held.
TEST(TextFile, ASparseFileIsRefusedFromItsFirstBytes) {
  const test::TempDir dir;
  const double growth = peak_growth_mib([&] {
    for (const std::string name : {"big.ply", "big.obj", "big.off", "big.stl"}) {
      const std::string path = dir.file(name);
      std::filesystem::resize_file(dir.write(name, ""), 2ull << 30);
      const std::string error = error_of([&] { read_mesh(path); });
      EXPECT_EQ(error.rfind(path + ": ", 0), 0u) << error;
      EXPECT_NE(error.find(name == "big.ply"   ? "not a PLY file"
                           : name == "big.stl" ? "binary STL"
                                               : "NUL"),
                std::string::npos)
          << error;
    }
  });
  EXPECT_LT(growth, 256.0);
}

TEST(TextFile, EmptyFilesAreNamedAsEmpty) {
  const test::TempDir dir;
  for (const std::string name : {"e.ply", "e.obj", "e.off", "e.stl"})
    EXPECT_EQ(error_of([&] { read_mesh(dir.write(name, "")); }), dir.file(name) + ": the file is empty");
}

// The check sees the first bytes only, then the whole file is read, and no more than its size.
TEST(TextFile, TheHeadCheckSeesTheFirstBytesThenTheWholeFileIsRead) {
  const test::TempDir dir;
  const std::string contents = std::string(3 * kHeadBytes + 17, 'x');
  const std::string path = dir.write("long.txt", contents);
  size_t seen = 0, declared = 0;
  const std::string read = read_text_file(path, [&](std::string_view head, size_t size) {
    seen = head.size();
    declared = size;
  });
  EXPECT_EQ(seen, kHeadBytes);
  EXPECT_EQ(declared, contents.size());
  EXPECT_EQ(read, contents);
  EXPECT_EQ(error_of([&] { read_text_file(path, [](std::string_view, size_t) { throw Error("not this"); }); }),
            path + ": not this");
}

// Two faces on the same vertices close up on their own (a pillow, which no subdivision can refine):
// refused at load, naming the second as a duplicate of the first, as the file numbers them, and the repair.
TEST(TextFile, AClosedPillowOfTwoFacesIsRefusedNamingThem) {
  const test::TempDir dir;
  const std::string path = dir.write("pillow.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 2\n");
  EXPECT_EQ(error_of([&] { read_mesh(path); }),
            path + ": 1 duplicate face (on the vertices of an earlier one), face 2 (line 5) as face 1 (line 4); "
                   "--repair drops it");
  const std::string quads = dir.write("quads.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nf 4 3 2 1\n");
  EXPECT_NE(error_of([&] { read_mesh(quads); }).find("face 2 (line 6) as face 1 (line 5); --repair drops it"),
            std::string::npos);
  const std::string ply = dir.write("pillow.ply",
                                    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                    "property float z\nelement face 2\nproperty list uchar int vertex_indices\n"
                                    "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n");
  EXPECT_EQ(error_of([&] { read_mesh(ply); }),
            ply + ": 1 duplicate face (on the vertices of an earlier one), face 1 as face 0; --repair drops it")
      << "PLY numbers its elements from 0, without lines";
}

}  // namespace
}  // namespace gps
