#include "render/image/image_io.h"

#include <filesystem>
#include <unistd.h>

#include "core/io/mesh_io.h"
#include "core/support/error.h"
#include "render/image/image_file_module.h"
#include "render/image/png_file.h"

namespace gps {

Image read_image(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw Error(path + ": no such file");
  if (std::filesystem::is_directory(path, ec)) throw Error(path + ": is a directory, not an image");
  if (is_png_file(path)) return read_png(path);
  Image image;
  if (const std::string failure = openimageio_files(path + ": cannot read the image").read(path, image);
      !failure.empty())
    throw Error(failure);
  return image;
}

const std::vector<std::string> kPositionChannels = {"P.X", "P.Y", "P.Z", "P.coverage"};
const std::vector<std::string> kNormalChannels = {"N.X", "N.Y", "N.Z", "N.kind"};

std::vector<std::string> read_channel_names(const std::string& path) {
  if (is_png_file(path)) {
    static const std::vector<std::vector<std::string>> kPngChannels = {
        {"Y"}, {"Y", "A"}, {"R", "G", "B"}, {"R", "G", "B", "A"}};
    return kPngChannels[size_t(png_channels(path) - 1)];
  }
  std::vector<std::string> names;
  if (const std::string failure = openimageio_files(path + ": cannot read the image").channel_names(path, names);
      !failure.empty())
    throw Error(failure);
  return names;
}

void write_image(const std::string& path, const Image& image, const std::vector<std::string>& channel_names) {
  namespace fs = std::filesystem;
  const std::string ext = extension_of(path);
  const fs::path dir = fs::path(path).parent_path().empty() ? fs::path(".") : fs::path(path).parent_path();
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw Error(path + ": cannot write, folder " + dir.string() + " does not exist");
  // The temporary keeps the extension so that OpenImageIO picks the format from it.
  const fs::path temp = dir / ("." + fs::path(path).stem().string() + ".tmp" + std::to_string(::getpid()) + ext);
  try {
    if (ext == ".png") {
      write_png(temp.string(), image, path);
    } else if (const std::string failure = openimageio_files(path + ": cannot write the image")
                                               .write(temp.string(), path, ext, image, channel_names);
               !failure.empty()) {
      throw Error(failure);
    }
  } catch (...) {
    fs::remove(temp, ec);
    throw;
  }
  fs::rename(temp, path, ec);
  if (ec) {
    fs::remove(temp, ec);
    throw Error(path + ": cannot replace the file (" + ec.message() + ")");
  }
}

}  // namespace gps
