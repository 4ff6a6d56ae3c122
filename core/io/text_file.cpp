#include "core/io/text_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/mesh/error.h"

namespace gps {

std::string read_text_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw Error(path + ": no such file");
  if (std::filesystem::is_directory(path, ec)) throw Error(path + ": is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot open (" + std::strerror(errno) + ")");
  // The whole file in one string of its own size (a growing stream buffer would hold up to twice it),
  // then whatever a pipe or a file still growing adds past that size.
  const auto size = std::filesystem::file_size(path, ec);
  std::string data(ec ? 0 : size_t(size), '\0');
  in.read(data.data(), std::streamsize(data.size()));
  data.resize(size_t(in.gcount()));
  if (in.bad()) throw Error(path + ": cannot read");
  if (in) {
    std::ostringstream rest;
    rest << in.rdbuf();
    data += std::move(rest).str();
  }
  return data;
}

}  // namespace gps
