#pragma once
// What a save is about to replace, checked before anything is written (docs/design.md §4).
#include <sys/types.h>

#include <filesystem>
#include <string>

namespace gps {

/// The file a save writes: the path after symbolic links and what is there now.
struct SaveTarget {
  std::filesystem::path file;  ///< `path` with its symbolic links followed (a dangling one: its missing target)
  std::filesystem::path folder;
  bool exists = false;
  mode_t mode = 0;
  nlink_t links = 0;  ///< names of the existing file; more than one: it is written in place
  dev_t device = 0;
  ino_t inode = 0;
};

/// Follows the symbolic links of `path` and checks what a save would replace. Throws gps::Error
/// naming `path` for a loop of links, an existing target that is not a regular file (a directory,
/// FIFO, device or socket), one that is read-only (no write permission bit set, or none for us), and
/// a folder that does not exist.
SaveTarget inspect_save_target(const std::string& path);

}  // namespace gps
