#include "core/io/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/mesh/error.h"

namespace gps {

namespace fs = std::filesystem;

namespace {

// The temporary file of the save in progress, for the signal handler (async-signal-safe: a plain
// buffer, unlink, then the default action re-raised).
char g_temp_path[4096];
volatile sig_atomic_t g_temp_active = 0;
constexpr int kCleanupSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};

extern "C" void remove_temp_and_reraise(int sig) {
  if (g_temp_active) ::unlink(g_temp_path);
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

// While alive, SIGINT/SIGTERM/SIGHUP/SIGQUIT remove `temp` before the process ends as they would have.
class TempFileSignalGuard {
public:
  explicit TempFileSignalGuard(const fs::path& temp) {
    const std::string s = temp.string();
    if (s.size() >= sizeof g_temp_path) return;  // no cleanup for absurdly long paths; the next save clears it
    std::memcpy(g_temp_path, s.c_str(), s.size() + 1);
    struct sigaction action {};
    action.sa_handler = remove_temp_and_reraise;
    sigemptyset(&action.sa_mask);
    for (size_t i = 0; i < std::size(kCleanupSignals); ++i) sigaction(kCleanupSignals[i], &action, &previous_[i]);
    g_temp_active = 1;
    installed_ = true;
  }
  ~TempFileSignalGuard() {
    if (!installed_) return;
    g_temp_active = 0;
    for (size_t i = 0; i < std::size(kCleanupSignals); ++i) sigaction(kCleanupSignals[i], &previous_[i], nullptr);
  }
  TempFileSignalGuard(const TempFileSignalGuard&) = delete;
  TempFileSignalGuard& operator=(const TempFileSignalGuard&) = delete;

private:
  struct sigaction previous_[std::size(kCleanupSignals)]{};
  bool installed_ = false;
};

// The file a path names after following symbolic links (a dangling link names its missing target),
// so that a save writes through the link and keeps it.
fs::path follow_links(fs::path path) {
  std::error_code ec;
  for (int hops = 0; hops < 40 && fs::is_symlink(fs::symlink_status(path, ec)); ++hops) {
    const fs::path link = fs::read_symlink(path, ec);
    if (ec) break;
    path = link.is_absolute() ? link : path.parent_path() / link;
  }
  return path;
}

// Flushes a file or folder to the disk; throws naming `path` when the system refuses.
void sync_path(const fs::path& what, const std::string& path) {
  const int fd = ::open(what.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0 || ::fsync(fd) != 0) {
    const std::string why = std::strerror(errno);
    if (fd >= 0) ::close(fd);
    throw Error(path + ": cannot flush " + what.string() + " to disk (" + why + ")");
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

}  // namespace

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write, bool binary) {
  std::error_code ec;
  const fs::path target = follow_links(fs::path(path));
  if (fs::is_directory(target, ec)) throw Error(path + ": is a directory");
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  if (!fs::is_directory(dir, ec)) throw Error(path + ": cannot write, folder " + dir.string() + " does not exist");
  remove_stale_temps(dir, target.filename().string());
  const fs::path temp = dir / ("." + target.filename().string() + ".tmp" + std::to_string(::getpid()));
  const TempFileSignalGuard guard(temp);
  try {
    std::ofstream out(temp, binary ? std::ios::binary : std::ios::out);
    if (!out) throw Error(path + ": cannot write (" + std::strerror(errno) + ")");
    write(out);
    out.flush();
    if (!out) throw Error(path + ": writing failed (" + std::strerror(errno) + ")");
    out.close();
    struct stat old {};
    if (::stat(target.c_str(), &old) == 0) ::chmod(temp.c_str(), old.st_mode & 07777);  // keep the old file's mode
    sync_path(temp, path);  // the data on disk before the name points at it
    sync_path(dir, path);   // and the temporary file's own entry in its folder
    fs::rename(temp, target, ec);
    if (ec) throw Error(path + ": cannot replace the file (" + ec.message() + ")");
    sync_path(dir, path);  // the rename itself on disk
  } catch (...) {
    fs::remove(temp, ec);
    throw;
  }
}

}  // namespace gps
