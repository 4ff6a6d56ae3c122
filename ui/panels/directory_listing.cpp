#include "ui/panels/directory_listing.h"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <filesystem>
#include <utility>
#include <unistd.h>

#include "core/support/error.h"

namespace gps {
namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

}  // namespace

bool has_extension(const std::string& name, const std::vector<std::string>& extensions) {
  const auto same = [](unsigned char a, unsigned char b) { return std::tolower(a) == std::tolower(b); };
  return std::any_of(extensions.begin(), extensions.end(), [&](const std::string& e) {
    return name.size() > e.size() && std::equal(e.begin(), e.end(), name.end() - std::ptrdiff_t(e.size()), same);
  });
}

std::vector<DirectoryEntry> list_directory(const std::string& directory, const std::vector<std::string>& extensions,
                                           bool show_hidden) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::directory_iterator it(directory, ec);
  if (ec) throw Error(directory + ": cannot list the folder (" + ec.message() + ")");
  std::vector<std::pair<std::string, DirectoryEntry>> keyed;  // (lower-case name, entry)
  for (; it != fs::directory_iterator(); it.increment(ec)) {  // a failed step ends the loop with ec set
    const std::string name = it->path().filename().string();
    if (!show_hidden && name.starts_with('.')) continue;
    std::error_code entry_ec;
    const fs::file_status status = it->status(entry_ec);  // follows links: a broken link fails here
    if (entry_ec) continue;
    if (fs::is_directory(status)) {
      if (::access(it->path().c_str(), R_OK | X_OK) == 0) keyed.push_back({lower(name), {name, true, 0}});
    } else if (fs::is_regular_file(status) && (extensions.empty() || has_extension(name, extensions))) {
      const std::uintmax_t size = it->file_size(entry_ec);
      if (!entry_ec && ::access(it->path().c_str(), R_OK) == 0) keyed.push_back({lower(name), {name, false, size}});
    }
  }
  if (ec) throw Error(directory + ": cannot list the folder (" + ec.message() + ")");
  std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) {
    if (a.second.is_directory != b.second.is_directory) return a.second.is_directory;
    return a.first != b.first ? a.first < b.first : a.second.name < b.second.name;
  });
  std::vector<DirectoryEntry> entries;
  entries.reserve(keyed.size());
  for (auto& [key, entry] : keyed) entries.push_back(std::move(entry));
  return entries;
}

}  // namespace gps
