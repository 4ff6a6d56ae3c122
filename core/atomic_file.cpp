#include "core/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "core/error.h"

namespace gps {

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write, bool binary) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  std::error_code ec;
  if (fs::is_directory(target, ec)) throw Error(path + ": is a directory");
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  if (!fs::is_directory(dir, ec)) throw Error(path + ": cannot write, folder " + dir.string() + " does not exist");
  const fs::path temp = dir / ("." + target.filename().string() + ".tmp" + std::to_string(::getpid()));
  try {
    std::ofstream out(temp, binary ? std::ios::binary : std::ios::out);
    if (!out) throw Error(path + ": cannot write (" + std::strerror(errno) + ")");
    write(out);
    out.flush();
    if (!out) throw Error(path + ": writing failed (" + std::strerror(errno) + ")");
    out.close();
    fs::rename(temp, target, ec);
    if (ec) throw Error(path + ": cannot replace the file (" + ec.message() + ")");
  } catch (...) {
    fs::remove(temp, ec);
    throw;
  }
}

}  // namespace gps
