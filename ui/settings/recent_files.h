#pragma once
// The editor's "recent files": most recent first, absolute paths, kept in a small text file.
#include <cstddef>
#include <string>
#include <vector>

namespace gps {

class RecentFiles {
public:
  /// Reads the list from `store`, one path per line (a missing or unreadable file is an empty list;
  /// empty lines are skipped); an empty `store` keeps the list in memory only.
  explicit RecentFiles(std::string store, std::size_t capacity = 10);

  /// $XDG_CONFIG_HOME/gpsurf/recent.txt, else $HOME/.config/gpsurf/recent.txt; "" when neither is set.
  static std::string default_store();

  /// Moves `path` (made absolute and lexically normal) to the front, drops the oldest past capacity
  /// and saves. A failed save never throws: it is kept in last_error() (cleared by the next good save).
  void add(const std::string& path);
  /// Drops `path` (compared after making it absolute and normal, as add() does) and saves.
  void remove(const std::string& path);

  /// The paths, most recent first.
  const std::vector<std::string>& paths() const { return paths_; }
  /// Why the last save failed, one line naming the file; "" after a good save.
  const std::string& last_error() const { return last_error_; }

private:
  void save();

  std::string store_;
  std::size_t capacity_;
  std::vector<std::string> paths_;
  std::string last_error_;
};

}  // namespace gps
