#include "render/image/png_file.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

#include "core/support/error.h"

namespace gps {
namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

// libpng reports errors by longjmp to the setjmp of its caller: the functions that call it hold
// only plain values and what they fill, so that nothing is skipped that needs destroying.
struct PngRead {
  png_structp png = nullptr;
  png_infop info = nullptr;
  char message[200] = "";
  ~PngRead() { png_destroy_read_struct(&png, &info, nullptr); }
};

void keep_error(png_structp png, png_const_charp message) {
  auto* state = static_cast<char*>(png_get_error_ptr(png));
  std::snprintf(state, 200, "%s", message);
  png_longjmp(png, 1);
}
void ignore_warning(png_structp, png_const_charp) {}

// Sets the size, channels, bit depth and alpha's gamma, then (unless `header_only`) reads the rows
// into `bytes`; false on a libpng error or an image too large.
bool read_rows(PngRead& r, std::FILE* file, bool header_only, std::vector<uint8_t>& bytes, int& width, int& height,
               int& channels, int& depth, float& gamma) {
  if (setjmp(png_jmpbuf(r.png))) return false;
  png_init_io(r.png, file);
  png_read_info(r.png, r.info);
  // The gamma alpha is associated under: a gAMA chunk's (1 / its value, to the hundredth) unless an
  // sRGB chunk says sRGB.
  int intent = 0;
  double file_gamma = 0.0;
  gamma = 1.0f;
  if (!png_get_sRGB(r.png, r.info, &intent) && png_get_gAMA(r.png, r.info, &file_gamma) && file_gamma > 0.0)
    gamma = std::round(100.0f * float(1.0 / file_gamma)) / 100.0f;
  png_set_expand(r.png);  // palette → RGB, grey below 8 bits → 8 bits, tRNS → alpha
  if (png_get_bit_depth(r.png, r.info) == 16) png_set_swap(r.png);
  png_set_interlace_handling(r.png);
  png_read_update_info(r.png, r.info);
  width = int(png_get_image_width(r.png, r.info));
  height = int(png_get_image_height(r.png, r.info));
  channels = int(png_get_channels(r.png, r.info));
  depth = int(png_get_bit_depth(r.png, r.info));
  if (header_only) return true;
  if (const std::string problem = image_size_problem(width, height, channels); !problem.empty()) {
    std::snprintf(r.message, sizeof r.message, "%s", problem.c_str());
    return false;
  }
  const size_t row_bytes = png_get_rowbytes(r.png, r.info);
  bytes.resize(row_bytes * size_t(height));
  std::vector<png_bytep> rows(static_cast<size_t>(height));
  for (int y = 0; y < height; ++y) rows[size_t(y)] = bytes.data() + row_bytes * size_t(y);
  png_read_image(r.png, rows.data());
  png_read_end(r.png, nullptr);
  return true;
}

struct PngWrite {
  png_structp png = nullptr;
  png_infop info = nullptr;
  char message[200] = "";
  ~PngWrite() { png_destroy_write_struct(&png, &info); }
};

bool write_rows(PngWrite& w, std::FILE* file, const std::vector<uint8_t>& bytes, int width, int height, int channels) {
  if (setjmp(png_jmpbuf(w.png))) return false;
  static constexpr int kTypes[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                                   PNG_COLOR_TYPE_RGB_ALPHA};
  png_init_io(w.png, file);
  png_set_IHDR(w.png, w.info, png_uint_32(width), png_uint_32(height), 8, kTypes[channels - 1], PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(w.png, w.info);
  const size_t row_bytes = size_t(width) * size_t(channels);
  for (int y = 0; y < height; ++y) png_write_row(w.png, bytes.data() + row_bytes * size_t(y));
  png_write_end(w.png, nullptr);
  return true;
}

// PNG stores colour unassociated with alpha, gpsurf's images associated (premultiplied): what
// OpenImageIO converts, in integers, after quantising on write and before scaling on read.
// Under a gamma g other than 1 the colour is associated in linear light: D · (alpha / max)^g.
template <class T>
void associate_alpha(T* samples, size_t pixels, int channels, float gamma) {
  constexpr unsigned max = std::numeric_limits<T>::max();
  for (size_t p = 0; p < pixels; ++p, samples += channels) {
    if (gamma == 1.0f) {
      for (int c = 0; c + 1 < channels; ++c) samples[c] = T((unsigned(samples[c]) * samples[channels - 1]) / max);
      continue;
    }
    const float alpha = std::pow(float(samples[channels - 1]) * (1.0f / float(max)), gamma);
    for (int c = 0; c + 1 < channels; ++c) samples[c] = T(float(samples[c]) * alpha);
  }
}
void deassociate_alpha(uint8_t* samples, size_t pixels, int channels) {
  for (size_t p = 0; p < pixels; ++p, samples += channels)
    if (const unsigned alpha = samples[channels - 1]; alpha != 0)
      for (int c = 0; c + 1 < channels; ++c) samples[c] = uint8_t(std::min(255u, samples[c] * 255u / alpha));
}

uint8_t to_byte(float v) {
  if (!(v > 0.0f)) return 0;  // NaN too
  return uint8_t(std::round(std::min(v, 1.0f) * 255.0f));
}

}  // namespace

bool is_png_file(const std::string& path) {
  const File file(std::fopen(path.c_str(), "rb"));
  png_byte signature[8];
  return file && std::fread(signature, 1, 8, file.get()) == 8 && png_sig_cmp(signature, 0, 8) == 0;
}

namespace {

struct PngContents {
  std::vector<uint8_t> bytes;  // empty where only the header was read
  int width = 0, height = 0, channels = 0, depth = 0;
  float gamma = 1.0f;
};

PngContents read_contents(const std::string& path, bool header_only) {
  const File file(std::fopen(path.c_str(), "rb"));
  if (!file) throw Error(path + ": cannot read the image (cannot open the file)");
  PngRead r;
  r.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, r.message, keep_error, ignore_warning);
  if (r.png) r.info = png_create_info_struct(r.png);
  if (!r.png || !r.info) throw Error(path + ": cannot read the image (out of memory)");
  PngContents c;
  if (!read_rows(r, file.get(), header_only, c.bytes, c.width, c.height, c.channels, c.depth, c.gamma))
    throw Error(path + ": cannot read the image data (" + std::string(r.message) + ")");
  return c;
}

}  // namespace

int png_channels(const std::string& path) { return read_contents(path, true).channels; }

Image read_png(const std::string& path) {
  PngContents contents = read_contents(path, false);
  std::vector<uint8_t>& bytes = contents.bytes;
  const int width = contents.width, height = contents.height, channels = contents.channels;
  const int depth = contents.depth;
  const float gamma = contents.gamma;
  Image image;
  image.width = width;
  image.height = height;
  image.channels = channels;
  const size_t n = size_t(width) * size_t(height) * size_t(channels);
  image.pixels.resize(n);
  const bool alpha = channels == 2 || channels == 4;
  const size_t pixels = size_t(width) * size_t(height);
  if (depth == 16) {
    std::vector<uint16_t> samples(n);
    std::memcpy(samples.data(), bytes.data(), 2 * n);
    if (alpha) associate_alpha(samples.data(), pixels, channels, gamma);
    for (size_t i = 0; i < n; ++i) image.pixels[i] = float(samples[i]) * (1.0f / 65535.0f);
  } else {
    if (alpha) associate_alpha(bytes.data(), pixels, channels, gamma);
    for (size_t i = 0; i < n; ++i) image.pixels[i] = float(bytes[i]) * (1.0f / 255.0f);
  }
  return image;
}

void write_png(const std::string& path, const Image& image, const std::string& shown_path) {
  if (image.channels < 1 || image.channels > 4)
    throw Error(shown_path + ": a PNG holds 1 to 4 channels, not " + std::to_string(image.channels));
  std::vector<uint8_t> bytes(image.pixels.size());
  std::transform(image.pixels.begin(), image.pixels.end(), bytes.begin(), to_byte);
  if (image.channels == 2 || image.channels == 4)
    deassociate_alpha(bytes.data(), size_t(image.width) * size_t(image.height), image.channels);
  const File file(std::fopen(path.c_str(), "wb"));
  if (!file) throw Error(shown_path + ": writing the image failed (cannot create the file)");
  PngWrite w;
  w.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, w.message, keep_error, ignore_warning);
  if (w.png) w.info = png_create_info_struct(w.png);
  if (!w.png || !w.info) throw Error(shown_path + ": writing the image failed (out of memory)");
  if (!write_rows(w, file.get(), bytes, image.width, image.height, image.channels) || std::fflush(file.get()) != 0 ||
      std::ferror(file.get()))
    throw Error(shown_path + ": writing the image failed");
}

}  // namespace gps
