#include "core/io/save_target.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "core/io/file_kind.h"
#include "core/support/quoted_text.h"
#include "core/support/error.h"

namespace gps {

namespace fs = std::filesystem;

namespace {

// As many links as the kernel follows before it reports a loop (Linux's MAXSYMLINKS).
constexpr int kMaxLinkHops = 40;

std::string octal_mode(mode_t mode) {
  char text[8];
  std::snprintf(text, sizeof text, "%04o", unsigned(mode & 07777));
  return text;
}

}  // namespace

SaveTarget inspect_save_target(const std::string& path) {
  const std::string name = escaped(path);
  SaveTarget target;
  target.file = fs::path(path);
  struct stat status {};
  int hops = 0;
  for (;; ++hops) {
    if (::lstat(target.file.c_str(), &status) != 0) {
      if (errno == ENOENT) break;  // a new file, or the missing target of a dangling link
      if (errno == ELOOP) throw Error(name + ": a loop of symbolic links; nothing written");
      throw Error(name + ": cannot write (" + std::strerror(errno) + ")");
    }
    if (!S_ISLNK(status.st_mode)) {
      target.exists = true;
      break;
    }
    if (hops == kMaxLinkHops) throw Error(name + ": a loop of symbolic links; nothing written");
    std::error_code ec;
    const fs::path link = fs::read_symlink(target.file, ec);
    if (ec)
      throw Error(name + ": cannot read the symbolic link " + escaped(target.file.string()) + " (" + ec.message() +
                  ")");
    target.file = link.is_absolute() ? link : target.file.parent_path() / link;
  }
  target.folder = target.file.parent_path().empty() ? fs::path(".") : target.file.parent_path();
  if (!target.exists) {
    std::error_code ec;
    if (!fs::is_directory(target.folder, ec))
      throw Error(name + ": cannot write, folder " + escaped(target.folder.string()) + " does not exist");
    return target;
  }
  if (S_ISDIR(status.st_mode)) throw Error(name + ": is a directory");
  if (!S_ISREG(status.st_mode))
    throw Error(name + ": is " + file_kind(status.st_mode) + ", not a regular file; nothing written");
  // Read-only as editors judge it: no write permission bit at all (which root's access() would pass),
  // or none for this process.
  const std::string keep = "; not replaced (make it writable or save under another name)";
  if ((status.st_mode & 0222) == 0)
    throw Error(name + ": is read-only (mode " + octal_mode(status.st_mode) + ")" + keep);
  if (::access(target.file.c_str(), W_OK) != 0) {
    if (errno == EACCES)
      throw Error(name + ": is not writable by this user (mode " + octal_mode(status.st_mode) + ")" + keep);
    if (errno == EROFS) throw Error(name + ": is on a read-only file system; nothing written");
    throw Error(name + ": cannot write (" + std::strerror(errno) + ")");
  }
  target.mode = status.st_mode;
  target.links = status.st_nlink;
  target.device = status.st_dev;
  target.inode = status.st_ino;
  return target;
}

}  // namespace gps
