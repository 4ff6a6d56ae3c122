#include "render/image/image_io.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <filesystem>
#include <unistd.h>

#include "core/support/error.h"
#include "core/io/mesh_io.h"

namespace gps {

Image read_image(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw Error(path + ": no such file");
  if (std::filesystem::is_directory(path, ec)) throw Error(path + ": is a directory, not an image");
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw Error(path + ": cannot read the image (" + OIIO::geterror().substr(0, 120) + ")");
  const OIIO::ImageSpec& spec = in->spec();
  Image image;
  image.width = spec.width;
  image.height = spec.height;
  image.channels = spec.nchannels;
  image.pixels.resize(size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels));
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
    throw Error(path + ": cannot read the image data (truncated or corrupt)");
  return image;
}

const std::vector<std::string> kPositionChannels = {"P.X", "P.Y", "P.Z", "P.coverage"};
const std::vector<std::string> kNormalChannels = {"N.X", "N.Y", "N.Z", "N.kind"};

std::vector<std::string> read_channel_names(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw Error(path + ": cannot read the image (" + OIIO::geterror().substr(0, 120) + ")");
  return in->spec().channelnames;
}

void write_image(const std::string& path, const Image& image, const std::vector<std::string>& channel_names) {
  namespace fs = std::filesystem;
  const std::string ext = extension_of(path);
  const fs::path dir = fs::path(path).parent_path().empty() ? fs::path(".") : fs::path(path).parent_path();
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw Error(path + ": cannot write, folder " + dir.string() + " does not exist");
  // The temporary keeps the extension so that OpenImageIO picks the format from it.
  const fs::path temp = dir / ("." + fs::path(path).stem().string() + ".tmp" + std::to_string(::getpid()) + ext);
  auto out = OIIO::ImageOutput::create(temp.string());
  if (!out) throw Error(path + ": cannot write images of type '" + ext + "'");
  const bool is_float = ext == ".exr" || ext == ".hdr";
  OIIO::ImageSpec spec(image.width, image.height, image.channels,
                       is_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  if (channel_names.size() == size_t(image.channels)) spec.channelnames = channel_names;
  if (!out->open(temp.string(), spec) || !out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data()) ||
      !out->close()) {
    fs::remove(temp, ec);
    throw Error(path + ": writing the image failed");
  }
  fs::rename(temp, path, ec);
  if (ec) {
    fs::remove(temp, ec);
    throw Error(path + ": cannot replace the file (" + ec.message() + ")");
  }
}

}  // namespace gps
