// The module libgpsurf_openimageio.so: images of every format OpenImageIO knows (image_file_module.h).
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <string>

#include "render/image/image_file_module.h"
#include "render/image/line_plot_drawing.h"

namespace gps {
namespace {

std::string oiio_error() { return OIIO::geterror().substr(0, 120); }

// Why `path` did not open as an image, in our words where OpenImageIO's are about itself.
std::string open_problem(const std::string& path) {
  const std::string why = oiio_error();
  if (why.find("could not find a format reader") != std::string::npos)
    return path + ": cannot read the image (not an image format gpsurf reads: PNG, EXR, JPEG, TIFF, ...)";
  return path + ": cannot read the image (" + why + ")";
}

std::string read(const std::string& path, Image& image) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) return open_problem(path);
  const OIIO::ImageSpec& spec = in->spec();
  if (const std::string problem = image_size_problem(spec.width, spec.height, spec.nchannels); !problem.empty())
    return path + ": cannot read the image data (" + problem + ")";
  image.width = spec.width;
  image.height = spec.height;
  image.channels = spec.nchannels;
  image.pixels.resize(size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels));
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
    return path + ": cannot read the image data (truncated or corrupt)";
  return "";
}

std::string channel_names(const std::string& path, std::vector<std::string>& names) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) return open_problem(path);
  names = in->spec().channelnames;
  return "";
}

std::string write(const std::string& path, const std::string& shown_path, const std::string& ext, const Image& image,
                  const std::vector<std::string>& channel_names) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) return shown_path + ": cannot write images of type '" + ext + "'";
  const bool is_float = ext == ".exr" || ext == ".hdr";
  OIIO::ImageSpec spec(image.width, image.height, image.channels,
                       is_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  if (channel_names.size() == size_t(image.channels)) spec.channelnames = channel_names;
  if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data()) || !out->close())
    return shown_path + ": writing the image failed";
  return "";
}

constexpr ImageFileFunctions kFunctions{kImageFileLayout, sizeof(ImageFileFunctions), read, channel_names, write,
                                        draw_line_plot};

}  // namespace
}  // namespace gps

extern "C" __attribute__((visibility("default"))) const gps::ImageFileFunctions* gpsurf_image_file_functions() {
  return &gps::kFunctions;
}
