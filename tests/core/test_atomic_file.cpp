// Saves (core/io/atomic_file.h): through symbolic links, signals in the middle of a save, stale
// temporary files of earlier crashed saves, targets that are not regular files, hard-linked targets
// (and signals sent while they are written in place), read-only targets.
#include "core/io/atomic_file.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <cstring>

#include "core/support/error.h"
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

// The message of the error a save throws, or "" when it succeeds.
std::string save_error(const std::string& path, const std::string& text) {
  try {
    write_text(path, text);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(AtomicFile, RefusesTargetsThatAreNotRegularFilesBeforeWriting) {
  test::TempDir dir;
  ASSERT_EQ(::mkfifo(dir.file("pipe.ply").c_str(), 0644), 0);
  fs::create_directories(dir.path() / "folder.ply");
  // A device node of the test's own (the null device's numbers), reached through a link: never a
  // device of the system, which a save that wrongly replaced it would break. Only root may make one.
  const bool device = ::mknod(dir.file("null").c_str(), S_IFCHR | 0666, ::makedev(1, 3)) == 0;
  if (device) fs::create_symlink("null", dir.path() / "null.ply");
  const int sock = ::socket(AF_UNIX, SOCK_STREAM, 0);
  ASSERT_GE(sock, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  const std::string socket_path = dir.file("socket.ply");
  ASSERT_LT(socket_path.size(), sizeof address.sun_path);
  std::memcpy(address.sun_path, socket_path.c_str(), socket_path.size() + 1);
  ASSERT_EQ(::bind(sock, reinterpret_cast<const sockaddr*>(&address), sizeof address), 0);
  bool wrote = false;
  const auto writer = [&wrote](std::ostream& out) {
    wrote = true;
    out << "new";
  };
  std::vector<std::pair<std::string, std::string>> cases = {
      {"pipe.ply", "a FIFO"}, {"folder.ply", "is a directory"}, {"socket.ply", "a socket"}};
  if (device) cases.emplace_back("null.ply", "a character device");
  for (const auto& [name, kind] : cases) {
    try {
      write_file_atomically(dir.file(name), writer);
      ADD_FAILURE() << name << " was written";
    } catch (const Error& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(dir.file(name)), std::string::npos) << message;
      EXPECT_NE(message.find(kind), std::string::npos) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
  ::close(sock);
  EXPECT_FALSE(wrote);
  EXPECT_TRUE(fs::is_fifo(dir.path() / "pipe.ply"));
  EXPECT_TRUE(fs::is_directory(dir.path() / "folder.ply"));
  EXPECT_TRUE(fs::is_socket(dir.path() / "socket.ply"));
  if (device) {
    EXPECT_TRUE(fs::is_symlink(dir.path() / "null.ply"));
    EXPECT_TRUE(fs::is_character_file(dir.path() / "null"));
  }
  EXPECT_TRUE(others(dir.path(), {"pipe.ply", "folder.ply", "null.ply", "null", "socket.ply"}).empty());
}

TEST(AtomicFile, RefusesALoopOfSymbolicLinksAndKeepsTheLinks) {
  test::TempDir dir;
  fs::create_symlink("b.ply", dir.path() / "a.ply");
  fs::create_symlink("a.ply", dir.path() / "b.ply");
  fs::create_symlink("self.ply", dir.path() / "self.ply");
  for (const std::string name : {"a.ply", "self.ply"}) {
    const std::string message = save_error(dir.file(name), "new");
    EXPECT_NE(message.find("a loop of symbolic links"), std::string::npos) << message;
    EXPECT_NE(message.find(dir.file(name)), std::string::npos) << message;
  }
  EXPECT_TRUE(fs::is_symlink(dir.path() / "a.ply"));
  EXPECT_TRUE(fs::is_symlink(dir.path() / "b.ply"));
  EXPECT_TRUE(fs::is_symlink(dir.path() / "self.ply"));
  EXPECT_EQ(fs::read_symlink(dir.path() / "a.ply"), "b.ply");
  EXPECT_TRUE(others(dir.path(), {"a.ply", "b.ply", "self.ply"}).empty());
}

// A hard-linked file is written in place, so that both names see the new contents, after its old
// contents are kept beside it as NAME~.
TEST(AtomicFile, WritesAHardLinkedFileInPlaceAfterABackup) {
  test::TempDir dir;
  const std::string path = dir.write("m.ply", "old contents");
  fs::create_hard_link(path, dir.path() / "other.ply");
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  struct stat before {};
  ASSERT_EQ(::stat(path.c_str(), &before), 0);
  write_text(path, "new");
  struct stat after {};
  ASSERT_EQ(::stat(path.c_str(), &after), 0);
  EXPECT_EQ(after.st_ino, before.st_ino);
  EXPECT_EQ(after.st_nlink, 2u);
  EXPECT_EQ(contents(path), "new");
  EXPECT_EQ(contents(dir.file("other.ply")), "new");
  EXPECT_EQ(contents(dir.file("m.ply~")), "old contents");
  EXPECT_EQ(fs::status(path).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  write_text(dir.file("other.ply"), "newer, and longer");
  EXPECT_EQ(contents(path), "newer, and longer");
  EXPECT_EQ(contents(dir.file("other.ply~")), "new");
  EXPECT_TRUE(others(dir.path(), {"m.ply", "other.ply", "m.ply~", "other.ply~"}).empty());
}

// A child process with a second thread (as gpsurf's parallel loops leave) saves onto a hard-linked
// file and is sent a signal from outside as soon as the copy in place has begun: it dies of that
// signal, and both names see either the complete old or the complete new contents, never a mix.
TEST(AtomicFile, ASignalDuringAnInPlaceCopyLeavesACompleteFile) {
  const size_t size = size_t(24) << 20;
  for (const int sig : {SIGTERM, SIGINT, SIGHUP}) {
    test::TempDir dir;
    const std::string path = dir.write("m.ply", std::string(size, 'o'));
    fs::create_hard_link(path, dir.path() / "other.ply");
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      std::thread([] {
        for (;;) ::pause();
      }).detach();
      write_text(path, std::string(size, 'n'));
      for (;;) ::pause();  // the signal ends the child however far the save got
    }
    const int fd = ::open(path.c_str(), O_RDONLY);
    ASSERT_GE(fd, 0);
    char first = 'o';
    int status = 0;
    while (first != 'n' && ::waitpid(child, &status, WNOHANG) == 0) ASSERT_GE(::pread(fd, &first, 1, 0), 0);
    ::close(fd);
    ::kill(child, sig);
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << "signal " << sig;
    const std::string now = contents(path);
    EXPECT_TRUE(now == std::string(size, 'o') || now == std::string(size, 'n'))
        << "signal " << sig << ": " << now.size() << " bytes, " << std::count(now.begin(), now.end(), 'n')
        << " of them new";
    EXPECT_EQ(contents(dir.file("m.ply~")), std::string(size, 'o')) << "signal " << sig;
    EXPECT_TRUE(others(dir.path(), {"m.ply", "other.ply", "m.ply~"}).empty()) << "signal " << sig;
  }
}

TEST(AtomicFile, RefusesAHardLinkedFileWhoseBackupNameIsTaken) {
  test::TempDir dir;
  const std::string path = dir.write("m.ply", "old");
  fs::create_hard_link(path, dir.path() / "other.ply");
  fs::create_directories(dir.path() / "m.ply~");
  const std::string message = save_error(path, "new");
  EXPECT_NE(message.find("hard links"), std::string::npos) << message;
  EXPECT_NE(message.find("a directory"), std::string::npos) << message;
  EXPECT_EQ(contents(path), "old");
  EXPECT_TRUE(others(dir.path(), {"m.ply", "other.ply", "m.ply~"}).empty());
}

// A read-only file in a writable folder is not replaced, even where this process could (root).
TEST(AtomicFile, RefusesAReadOnlyTarget) {
  test::TempDir dir;
  const std::string path = dir.write("m.ply", "old");
  fs::permissions(path, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  bool wrote = false;
  try {
    write_file_atomically(path, [&wrote](std::ostream& out) {
      wrote = true;
      out << "new";
    });
    ADD_FAILURE() << "a read-only file was replaced";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("read-only (mode 0444)"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(wrote);
  EXPECT_EQ(contents(path), "old");
  EXPECT_EQ(fs::status(path).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  EXPECT_TRUE(others(dir.path(), {"m.ply"}).empty());
}

}  // namespace
}  // namespace gps
