// Saves (core/io/atomic_file.h): through symbolic links, signals in the middle of a save, stale
// temporary files of earlier crashed saves.
#include "core/io/atomic_file.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/mesh/error.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

namespace fs = std::filesystem;

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The names in a folder other than `keep`: temporary files a save left behind.
std::vector<std::string> others(const fs::path& dir, const std::vector<std::string>& keep) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir))
    if (std::find(keep.begin(), keep.end(), e.path().filename().string()) == keep.end())
      out.push_back(e.path().filename().string());
  return out;
}

void write_text(const std::string& path, const std::string& text) {
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

TEST(AtomicFile, WritesThroughASymbolicLinkAndKeepsIt) {
  test::TempDir dir;
  fs::create_directories(dir.path() / "real");
  const std::string target = dir.write("real/mesh.ply", "old");
  fs::create_symlink("real/mesh.ply", dir.path() / "link.ply");           // relative, as `ln -s` makes them
  fs::create_symlink(dir.path() / "link.ply", dir.path() / "link2.ply");  // a chain of two
  write_text(dir.file("link2.ply"), "new");
  EXPECT_TRUE(fs::is_symlink(dir.path() / "link.ply"));
  EXPECT_TRUE(fs::is_symlink(dir.path() / "link2.ply"));
  EXPECT_EQ(contents(target), "new");
  EXPECT_EQ(contents(dir.file("link2.ply")), "new");
  EXPECT_TRUE(others(dir.path() / "real", {"mesh.ply"}).empty());
  // A dangling link: the save creates its target.
  fs::create_symlink("real/fresh.ply", dir.path() / "dangling.ply");
  write_text(dir.file("dangling.ply"), "fresh");
  EXPECT_TRUE(fs::is_symlink(dir.path() / "dangling.ply"));
  EXPECT_EQ(contents(dir.file("real/fresh.ply")), "fresh");
}

TEST(AtomicFile, KeepsTheModeOfTheFileItReplaces) {
  test::TempDir dir;
  const std::string path = dir.write("m.ply", "old");
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  write_text(path, "new");
  EXPECT_EQ(fs::status(path).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
}

// A child process saves and is signalled while writing (the writer raises the signal half-way):
// it dies of the signal, the old file is intact and no temporary file is left.
TEST(AtomicFile, ASignalDuringASaveRemovesTheTemporaryFile) {
  for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
    test::TempDir dir;
    const std::string path = dir.write("m.ply", "old contents");
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      write_file_atomically(path, [sig](std::ostream& out) {
        out << std::string(1 << 20, 'x');
        out.flush();
        ::raise(sig);
        out << "never";
      });
      ::_exit(0);
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFSIGNALED(status)) << "signal " << sig;
    if (WIFSIGNALED(status)) {
      EXPECT_EQ(WTERMSIG(status), sig);
    }
    EXPECT_EQ(contents(path), "old contents") << "signal " << sig;
    EXPECT_TRUE(others(dir.path(), {"m.ply"}).empty()) << "signal " << sig << ": " << others(dir.path(), {"m.ply"})[0];
  }
}

// Temporary files of gpsurf's naming whose process is gone (a kill -9 mid-save) are removed by the
// next save beside them; files of other names, and of live processes, are left alone.
TEST(AtomicFile, TheNextSaveRemovesStaleTemporaryFiles) {
  test::TempDir dir;
  const std::string path = dir.write("m.ply", "old");
  const pid_t dead = ::fork();
  if (dead == 0) ::_exit(0);
  ::waitpid(dead, nullptr, 0);  // a process id that no longer runs
  const std::string stale = ".m.ply.tmp" + std::to_string(dead);
  const std::string live = ".m.ply.tmp1";  // init: alive (or not ours to judge)
  dir.write(stale, "debris");
  dir.write(live, "someone else's save");
  dir.write(".other.ply.tmp" + std::to_string(dead), "not ours to clear here");
  dir.write(".m.ply.tmpNOTAPID", "not our naming");
  write_text(path, "new");
  EXPECT_EQ(contents(path), "new");
  EXPECT_FALSE(fs::exists(dir.path() / stale));
  EXPECT_TRUE(fs::exists(dir.path() / live));
  EXPECT_TRUE(fs::exists(dir.path() / (".other.ply.tmp" + std::to_string(dead))));
  EXPECT_TRUE(fs::exists(dir.path() / ".m.ply.tmpNOTAPID"));
}

TEST(AtomicFile, AFailedWriteLeavesTheOldFileAndNoTemporaryFile) {
  test::TempDir dir;
  const std::string path = dir.write("m.ply", "old");
  EXPECT_THROW(write_file_atomically(path, [](std::ostream&) { throw Error("writer failed"); }), Error);
  EXPECT_EQ(contents(path), "old");
  EXPECT_TRUE(others(dir.path(), {"m.ply"}).empty());
}

}  // namespace
}  // namespace gps
