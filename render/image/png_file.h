#pragma once
// PNG files through libpng: the format of every screenshot, render and MatCap gpsurf writes, read
// and written without loading OpenImageIO (image_io.h sends the other formats there).
#include <string>

#include "render/image/image.h"

namespace gps {

/// Whether the file starts with PNG's signature (false if it cannot be read).
bool is_png_file(const std::string& path);

/// The channels read_png gives for the file, from its header alone. Throws gps::Error naming the file.
int png_channels(const std::string& path);

/// Reads a PNG as OpenImageIO reads it: the channels the file stores (grey, grey and alpha, RGB,
/// RGBA; a palette as RGB, or RGBA where it has transparency), each value over its bit depth's
/// maximum, colour associated with alpha (in linear light where a gAMA chunk asks). Throws
/// gps::Error naming the file.
Image read_png(const std::string& path);

/// Writes 1 to 4 channels as 8-bit PNG, each value v as round(255 · clamp(v, 0, 1)) (halves away
/// from zero, NaN as 0), as OpenImageIO converts floats to 8 bits. Writes `path` itself (image_io.h
/// makes the write atomic). Throws gps::Error naming `shown_path`.
void write_png(const std::string& path, const Image& image, const std::string& shown_path);

}  // namespace gps
