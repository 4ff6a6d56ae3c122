#include "core/io/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/io/file_kind.h"
#include "core/support/quoted_text.h"
#include "core/io/save_target.h"
#include "core/support/error.h"

namespace gps {

namespace fs = std::filesystem;

namespace {

// The temporary file of the save in progress, for the signal handler (async-signal-safe: a plain
// buffer, unlink, then the default action re-raised).
char g_temp_path[4096];
volatile sig_atomic_t g_temp_active = 0;
constexpr int kCleanupSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};

// While a hard-linked target is written in place, an ending signal is only noted here, whichever
// thread it reaches: the copy stops, the old contents are put back, and then the signal is raised.
std::atomic<bool> g_writing_in_place{false};
std::atomic<int> g_pending_signal{0};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free);

extern "C" void remove_temp_and_reraise(int sig) {
  if (g_writing_in_place) {
    g_pending_signal = sig;
    return;
  }
  if (g_temp_active) ::unlink(g_temp_path);
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

// While alive, SIGINT/SIGTERM/SIGHUP/SIGQUIT remove `temp` before the process ends as they would have.
class TempFileSignalGuard {
public:
  explicit TempFileSignalGuard(const fs::path& temp) {
    const std::string s = temp.string();
    if (s.size() < sizeof g_temp_path) {  // else no cleanup for absurdly long paths; the next save clears it
      std::memcpy(g_temp_path, s.c_str(), s.size() + 1);
      g_temp_active = 1;
    }
    struct sigaction action {};
    action.sa_handler = remove_temp_and_reraise;
    action.sa_flags = SA_RESTART;
    sigemptyset(&action.sa_mask);
    for (size_t i = 0; i < std::size(kCleanupSignals); ++i) sigaction(kCleanupSignals[i], &action, &previous_[i]);
  }
  ~TempFileSignalGuard() {
    g_temp_active = 0;
    for (size_t i = 0; i < std::size(kCleanupSignals); ++i) sigaction(kCleanupSignals[i], &previous_[i], nullptr);
  }
  TempFileSignalGuard(const TempFileSignalGuard&) = delete;
  TempFileSignalGuard& operator=(const TempFileSignalGuard&) = delete;

private:
  struct sigaction previous_[std::size(kCleanupSignals)]{};
};

// While alive, the ending signals are noted instead of acted on (see g_writing_in_place); at its end
// a noted one removes the temporary file and ends the process.
class InPlaceWrite {
public:
  InPlaceWrite() {
    g_pending_signal = 0;
    g_writing_in_place = true;
  }
  ~InPlaceWrite() {
    g_writing_in_place = false;
    if (const int sig = g_pending_signal.exchange(0)) remove_temp_and_reraise(sig);
  }
  InPlaceWrite(const InPlaceWrite&) = delete;
  InPlaceWrite& operator=(const InPlaceWrite&) = delete;
};

// Closes the descriptor however the save ends.
struct FileDescriptor {
  int fd;
  ~FileDescriptor() {
    if (fd >= 0) ::close(fd);
  }
};

// Copies every byte of the file `from` into the descriptor `to` from its start, cuts `to` to that
// length and flushes it to disk; returns an empty string, or what failed. With `stop`, a noted
// signal ends the copy early as a failure.
std::string copy_into(const fs::path& from, int to, const std::atomic<int>* stop = nullptr) {
  const FileDescriptor in{::open(from.c_str(), O_RDONLY | O_CLOEXEC)};
  if (in.fd < 0) return std::string("cannot open ") + escaped(from.string()) + " (" + std::strerror(errno) + ")";
  if (::lseek(to, 0, SEEK_SET) != 0) return std::strerror(errno);
  char buffer[1 << 16];
  off_t total = 0;
  for (;;) {
    if (stop && *stop) return "interrupted by signal " + std::to_string(stop->load());
    const ssize_t n = ::read(in.fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return std::string("cannot read ") + escaped(from.string()) + " (" + std::strerror(errno) + ")";
    if (n == 0) break;
    for (ssize_t done = 0; done < n;) {
      const ssize_t w = ::write(to, buffer + done, size_t(n - done));
      if (w < 0 && errno == EINTR) continue;
      if (w < 0) return std::strerror(errno);
      done += w;
    }
    total += n;
  }
  if (::ftruncate(to, total) != 0 || ::fsync(to) != 0) return std::strerror(errno);
  return {};
}

// Flushes a file or folder to the disk; throws with `name` (the save's path as messages show it) when
// the system refuses.
void sync_path(const fs::path& what, const std::string& name) {
  const int fd = ::open(what.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0 || ::fsync(fd) != 0) {
    const std::string why = std::strerror(errno);
    if (fd >= 0) ::close(fd);
    throw Error(name + ": cannot flush " + escaped(what.string()) + " to disk (" + why + ")");
  }
  ::close(fd);
}

// Removes temporary files of gpsurf's naming (".NAME.tmpPID") beside the target whose process is gone.
void remove_stale_temps(const fs::path& dir, const std::string& name) {
  const std::string prefix = "." + name + ".tmp";
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string file = it->path().filename().string();
    if (file.size() <= prefix.size() || file.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string pid = file.substr(prefix.size());
    if (pid.size() > 9 || pid.find_first_not_of("0123456789") != std::string::npos) continue;
    const pid_t owner = pid_t(std::stol(pid));
    if (owner == ::getpid() || (::kill(owner, 0) != 0 && errno == ESRCH)) {
      std::error_code ignored;
      fs::remove(it->path(), ignored);
    }
  }
}

// A file with more than one name (hard links) is written in place, so that every name keeps seeing
// it, as careful editors do: its old contents are first saved as NAME~ beside it (atomically, flushed),
// then the complete new contents in `temp` are copied over it. A failed copy, or one an ending signal
// interrupts, puts the old contents back (the signal then ends the process); where even that fails,
// the message names the backup.
void write_in_place(const SaveTarget& target, const fs::path& temp, const std::string& name) {
  const fs::path backup = target.file.string() + "~";
  const std::string shown_backup = escaped(backup.string());
  struct stat status {};
  if (::lstat(backup.c_str(), &status) == 0 && !S_ISREG(status.st_mode))
    throw Error(name + ": has " + std::to_string(target.links) +
                " hard links, so it is written in place after a backup to " + shown_backup + ", which is " +
                file_kind(status.st_mode) + "; nothing written");
  const InPlaceWrite in_place;
  const std::string backup_name = backup.filename().string();
  remove_stale_temps(target.folder, backup_name);
  const fs::path backup_temp = target.folder / ("." + backup_name + ".tmp" + std::to_string(::getpid()));
  {
    const FileDescriptor out{::open(backup_temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, target.mode & 0777)};
    const std::string failed = out.fd < 0 ? std::string(std::strerror(errno)) : copy_into(target.file, out.fd);
    if (!failed.empty()) {
      std::error_code ignored;
      fs::remove(backup_temp, ignored);
      throw Error(name + ": cannot keep a backup " + shown_backup + " before writing in place (" + failed + ")");
    }
  }
  std::error_code ec;
  fs::rename(backup_temp, backup, ec);
  if (ec) {
    fs::remove(backup_temp, ec);
    throw Error(name + ": cannot keep a backup " + shown_backup + " before writing in place (" + ec.message() + ")");
  }
  sync_path(target.folder, name);
  const FileDescriptor file{::open(target.file.c_str(), O_WRONLY | O_NOFOLLOW | O_CLOEXEC)};
  struct stat now {};
  if (file.fd < 0 || ::fstat(file.fd, &now) != 0 || now.st_dev != target.device || now.st_ino != target.inode)
    throw Error(name + ": changed while it was being saved; not written (the old contents are also in " + shown_backup +
                ")");
  const std::string failed = copy_into(temp, file.fd, &g_pending_signal);
  if (failed.empty()) return;
  if (copy_into(backup, file.fd).empty())
    throw Error(name + ": writing in place failed (" + failed + "); the old contents are back");
  throw Error(name + ": writing in place failed (" + failed + "); the old contents are in " + shown_backup);
}

}  // namespace

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write, bool binary) {
  const SaveTarget target = inspect_save_target(path);
  const std::string name = escaped(path);
  const fs::path& dir = target.folder;
  remove_stale_temps(dir, target.file.filename().string());
  const fs::path temp = dir / ("." + target.file.filename().string() + ".tmp" + std::to_string(::getpid()));
  const TempFileSignalGuard guard(temp);
  std::error_code ec;
  try {
    std::ofstream out(temp, binary ? std::ios::binary : std::ios::out);
    if (!out) throw Error(name + ": cannot write (" + std::strerror(errno) + ")");
    write(out);
    out.flush();
    if (!out) throw Error(name + ": writing failed (" + std::strerror(errno) + ")");
    out.close();
    if (target.exists) ::chmod(temp.c_str(), target.mode & 07777);  // keep the old file's mode
    sync_path(temp, name);                                          // the data on disk before the name points at it
    if (target.links > 1) {
      write_in_place(target, temp, name);
      fs::remove(temp, ec);
      return;
    }
    sync_path(dir, name);  // the temporary file's own entry in its folder
    fs::rename(temp, target.file, ec);
    if (ec) throw Error(name + ": cannot replace the file (" + ec.message() + ")");
    sync_path(dir, name);  // the rename itself on disk
  } catch (...) {
    fs::remove(temp, ec);
    throw;
  }
}

}  // namespace gps
