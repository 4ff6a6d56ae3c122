#pragma once
// The entries of one folder as a file dialog shows them: folders first, files filtered by extension.
#include <cstdint>
#include <string>
#include <vector>

namespace gps {

/// One listed name inside a folder (`size` is 0 for folders).
struct DirectoryEntry {
  std::string name;
  bool is_directory;
  std::uintmax_t size;
};

/// Whether `name` is longer than and ends with one of `extensions` (with dot, case-insensitive).
bool has_extension(const std::string& name, const std::vector<std::string>& extensions);

/// Entries of `directory`: sub-folders first, then files whose extension (case-insensitive, with dot,
/// e.g. ".ply") is in `extensions` (empty = all files); each group sorted by name (case-insensitive);
/// hidden entries (leading '.') only when `show_hidden`. Entries that cannot be read (no permission,
/// broken links, devices, sockets) are skipped. Throws gps::Error naming the folder when it cannot be read.
std::vector<DirectoryEntry> list_directory(const std::string& directory, const std::vector<std::string>& extensions,
                                           bool show_hidden = false);

}  // namespace gps
