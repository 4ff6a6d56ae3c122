#include "ui/settings/recent_files.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <utility>

#include "core/io/atomic_file.h"
#include "core/support/error.h"
#include "ui/settings/editor_settings.h"

namespace gps {
namespace {

/// `path` made absolute against the working folder and lexically normal ("" when that fails).
std::string normal_absolute(const std::string& path) {
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
  return ec ? std::string() : absolute.lexically_normal().string();
}

}  // namespace

RecentFiles::RecentFiles(std::string store, std::size_t capacity) : store_(std::move(store)), capacity_(capacity) {
  if (store_.empty()) return;
  std::ifstream in(store_);
  for (std::string line; paths_.size() < capacity_ && std::getline(in, line);) {
    if (!line.empty() && std::find(paths_.begin(), paths_.end(), line) == paths_.end()) paths_.push_back(line);
  }
}

std::string RecentFiles::default_store() {
  const std::string folder = config_folder();
  return folder.empty() ? "" : folder + "/recent.txt";
}

void RecentFiles::add(const std::string& path) {
  const std::string absolute = normal_absolute(path);
  if (path.empty() || absolute.empty() || absolute.find('\n') != std::string::npos) return;  // not storable
  std::erase(paths_, absolute);
  paths_.insert(paths_.begin(), absolute);
  if (paths_.size() > capacity_) paths_.resize(capacity_);
  save();
}

void RecentFiles::remove(const std::string& path) {
  if (std::erase(paths_, normal_absolute(path)) > 0) save();
}

void RecentFiles::save() {
  if (store_.empty()) return;
  try {
    std::error_code ec;
    const std::filesystem::path folder = std::filesystem::path(store_).parent_path();
    if (!folder.empty()) std::filesystem::create_directories(folder, ec);
    if (ec) throw Error(store_ + ": cannot create the folder " + folder.string() + " (" + ec.message() + ")");
    write_file_atomically(store_, [&](std::ostream& out) {
      for (const std::string& p : paths_) out << p << '\n';
    });
    last_error_.clear();
  } catch (const Error& e) {
    last_error_ = e.what();
  }
}

}  // namespace gps
