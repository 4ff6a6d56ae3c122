#include "render/image/image_io.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "core/io/atomic_file.h"
#include "core/io/mesh_io.h"
#include "core/io/save_target.h"
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

namespace {
// libjpeg's largest image side (JPEG_MAX_DIMENSION): past it, its error handler ends the process.
constexpr int kLargestJpegSide = 65500;
}  // namespace

void write_image(const std::string& path, const Image& image, const std::vector<std::string>& channel_names) {
  namespace fs = std::filesystem;
  const std::string ext = extension_of(path);
  // The image libraries divide by the width or end the process past JPEG's size: checked first.
  if (image.width < 1 || image.height < 1)
    throw Error(path + ": an image needs at least one pixel, got " + std::to_string(image.width) + "x" +
                std::to_string(image.height));
  if ((ext == ".jpg" || ext == ".jpeg") && std::max(image.width, image.height) > kLargestJpegSide)
    throw Error(path + ": a JPEG holds at most " + std::to_string(kLargestJpegSide) + " pixels a side, got " +
                std::to_string(image.width) + "x" + std::to_string(image.height));
  inspect_save_target(path);  // a target a save refuses is refused before the image is encoded
  const fs::path dir = fs::path(path).parent_path().empty() ? fs::path(".") : fs::path(path).parent_path();
  // Encoded into a scratch file that keeps the extension (OpenImageIO picks the format from it), then
  // saved as every file is (core/io/atomic_file.h): links, read-only targets and signals alike.
  const fs::path scratch = dir / ("." + fs::path(path).stem().string() + ".image" + std::to_string(::getpid()) + ext);
  std::error_code ec;
  try {
    if (ext == ".png") {
      write_png(scratch.string(), image, path);
    } else if (const std::string failure = openimageio_files(path + ": cannot write the image")
                                               .write(scratch.string(), path, ext, image, channel_names);
               !failure.empty()) {
      throw Error(failure);
    }
    write_file_atomically(
        path,
        [&](std::ostream& out) {
          std::ifstream in(scratch, std::ios::binary);
          if (!(out << in.rdbuf())) throw Error(path + ": writing the image failed");
        },
        true);
  } catch (...) {
    fs::remove(scratch, ec);
    throw;
  }
  fs::remove(scratch, ec);
}

}  // namespace gps
