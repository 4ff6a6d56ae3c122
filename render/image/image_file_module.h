#pragma once
// The formats besides PNG (EXR for the AOVs, and whatever else OpenImageIO knows) go through a module
// opened the first time one is needed (openimageio_files.cpp, built as libgpsurf_openimageio.so):
// OpenImageIO links some 260 libraries, and loading them cost every program start 0.4 s.
#include <cstddef>
#include <string>
#include <vector>

#include "render/image/image.h"
#include "render/image/line_plot.h"

namespace gps {

/// The layout of ImageFileFunctions: a module of another layout (another build's) is not used.
inline constexpr int kImageFileLayout = 1;

/// The module's functions; each returns "" or, on failure, the whole one-line message naming the file.
struct ImageFileFunctions {
  int layout = kImageFileLayout;
  size_t size = sizeof(ImageFileFunctions);
  std::string (*read)(const std::string& path, Image& image);
  std::string (*channel_names)(const std::string& path, std::vector<std::string>& names);
  /// Writes `path` itself in the format of `extension` (".exr"; 8 bits, or float for EXR and HDR);
  /// `shown_path` is the name the messages give.
  std::string (*write)(const std::string& path, const std::string& shown_path, const std::string& extension,
                       const Image& image, const std::vector<std::string>& channel_names);
  /// write_line_plot (line_plot.h), drawn with OpenImageIO's ImageBufAlgo.
  std::string (*line_plot)(const std::string& path, const std::string& title, const std::string& x_label,
                           const std::string& y_label, const std::vector<PlotSeries>& series, bool log_x, bool log_y);
};

/// The symbol the module exports: extern "C" const ImageFileFunctions* <kImageFileEntry>().
inline constexpr const char* kImageFileEntry = "gpsurf_image_file_functions";

/// The module's functions, loaded on the first call: from the folder of the program (or Python
/// module) that calls, the install's library folder beside it, or the build tree. Throws gps::Error
/// naming what it looked for where `what` (e.g. "x.exr: cannot read the image") cannot go on.
const ImageFileFunctions& openimageio_files(const std::string& what);

}  // namespace gps
