// PNG files through libpng (render/image/png_file.h) against OpenImageIO (through gpsurf's image
// module, render/image/image_file_module.h): the same pixels written and read, for every colour type
// and bit depth, alpha included (in linear light where a gAMA chunk asks); and OpenImageIO loaded only for the other
// formats.
#include <gtest/gtest.h>
#include <png.h>

#include <cmath>
#include <csetjmp>
#include <cstring>
#include <cstdio>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/support/error.h"
#include "render/image/image_file_module.h"
#include "render/image/image_io.h"
#include "render/image/png_file.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

// Values that test the conversion to 8 bits: out of range, not finite, every level, every level's
// half and the floats either side of it, and random ones.
std::vector<float> testing_values(int channels, bool opaque) {
  std::vector<float> v = {-1.0f,    0.0f,      1e-9f,   0.5f, 1.0f, 2.0f, std::numeric_limits<float>::quiet_NaN(),
                          INFINITY, -INFINITY, 0.99999f};
  for (int k = 0; k < 256; ++k) {
    const float half = (float(k) + 0.5f) / 255.0f;
    v.insert(v.end(), {float(k) / 255.0f, half, std::nextafter(half, 0.0f), std::nextafter(half, 1.0f)});
  }
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int i = 0; i < 2000; ++i) v.push_back(unit(random));
  while (v.size() % size_t(channels) != 0) v.push_back(0.25f);
  if (opaque)
    for (size_t i = size_t(channels) - 1; i < v.size(); i += size_t(channels)) v[i] = 1.0f;
  return v;
}

Image row_image(std::vector<float> values, int channels) {
  Image image;
  image.channels = channels;
  image.height = 2;
  values.insert(values.end(), values.begin(), values.end());
  image.width = int(values.size()) / channels / 2;
  image.pixels = std::move(values);
  return image;
}

Image read_by_openimageio(const std::string& path) {
  Image image;
  const std::string failure = openimageio_files(path).read(path, image);
  EXPECT_EQ(failure, "");
  return image;
}

void expect_same_image(const Image& a, const Image& b, const std::string& what) {
  ASSERT_EQ(a.width, b.width) << what;
  ASSERT_EQ(a.height, b.height) << what;
  ASSERT_EQ(a.channels, b.channels) << what;
  size_t differ = 0, first = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    if (a.pixels[i] != b.pixels[i] && differ++ == 0) first = i;
  EXPECT_EQ(differ, 0u) << what << ": first at sample " << first << ": " << a.pixels[first] << " against "
                        << b.pixels[first];
}

// A PNG written with libpng as a user's tools might write one: any colour type, bit depth, palette,
// transparency and interlacing. `samples`: one per channel per pixel (palette indices for a palette).
struct PngSpec {
  int width = 0, height = 0, colour_type = PNG_COLOR_TYPE_RGB, depth = 8;
  bool interlaced = false;
  std::vector<png_color> palette;
  std::vector<png_byte> transparency;  // per palette entry
  double file_gamma = 0.0;             // a gAMA chunk where positive
  bool srgb = false;                   // an sRGB chunk
  std::vector<unsigned> samples;
};

// Opens `path`, makes libpng's write structures, runs `write` on them (false: a libpng error), closes.
template <class Write>
void write_png_file(const std::string& path, Write write) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  ASSERT_NE(file, nullptr);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  const bool written = write(png, info, file);
  png_destroy_write_struct(&png, &info);
  std::fclose(file);
  ASSERT_TRUE(written) << path;
}

bool write_spec_rows(png_structp png, png_infop info, std::FILE* file, const PngSpec& spec,
                     std::vector<png_bytep>& rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, file);
  png_set_IHDR(png, info, png_uint_32(spec.width), png_uint_32(spec.height), spec.depth, spec.colour_type,
               spec.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  if (!spec.palette.empty()) png_set_PLTE(png, info, spec.palette.data(), int(spec.palette.size()));
  if (!spec.transparency.empty())
    png_set_tRNS(png, info, spec.transparency.data(), int(spec.transparency.size()), nullptr);
  if (spec.file_gamma > 0.0) png_set_gAMA(png, info, spec.file_gamma);
  if (spec.srgb) png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_write_info(png, info);
  if (spec.depth < 8) png_set_packing(png);
  if (spec.depth == 16) png_set_swap(png);
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  return true;
}

void write_spec(const std::string& path, const PngSpec& spec) {
  const int channels = spec.colour_type == PNG_COLOR_TYPE_GRAY         ? 1
                       : spec.colour_type == PNG_COLOR_TYPE_GRAY_ALPHA ? 2
                       : spec.colour_type == PNG_COLOR_TYPE_RGB        ? 3
                       : spec.colour_type == PNG_COLOR_TYPE_RGB_ALPHA  ? 4
                                                                       : 1;
  const size_t bytes_per_sample = spec.depth == 16 ? 2 : 1,
               row_bytes = size_t(spec.width * channels) * bytes_per_sample;
  std::vector<png_byte> data(row_bytes * size_t(spec.height));
  for (size_t i = 0; i < spec.samples.size(); ++i) {
    if (bytes_per_sample == 2) {
      const uint16_t v = uint16_t(spec.samples[i]);
      std::memcpy(data.data() + 2 * i, &v, 2);
    } else {
      data[i] = png_byte(spec.samples[i]);
    }
  }
  std::vector<png_bytep> rows(static_cast<size_t>(spec.height));
  for (int y = 0; y < spec.height; ++y) rows[size_t(y)] = data.data() + row_bytes * size_t(y);
  write_png_file(path, [&](png_structp png, png_infop info, std::FILE* file) {
    return write_spec_rows(png, info, file, spec, rows);
  });
}

TEST(PngFile, WritesThePixelsOpenImageIOWrites) {
  test::TempDir dir;
  for (int channels = 1; channels <= 4; ++channels)
    for (const bool opaque : {true, false}) {
      const Image image = row_image(testing_values(channels, opaque), channels);
      const std::string ours = dir.file("ours.png"), theirs = dir.file("theirs.png");
      write_image(ours, image);
      ASSERT_EQ(openimageio_files(theirs).write(theirs, theirs, ".png", image, {}), "");
      expect_same_image(read_by_openimageio(ours), read_by_openimageio(theirs),
                        std::to_string(channels) + " channels" + (opaque ? ", opaque" : ""));
      // And read back by libpng as OpenImageIO reads it.
      expect_same_image(read_image(theirs), read_by_openimageio(theirs), "read back");
    }
}

TEST(PngFile, ReadsEveryColourTypeAndDepthAsOpenImageIOReadsIt) {
  test::TempDir dir;
  std::mt19937 random(3);
  const auto spec = [&](int colour_type, int depth, int channels, bool interlaced = false) {
    PngSpec s;
    s.width = 37;
    s.height = 11;
    s.colour_type = colour_type;
    s.depth = depth;
    s.interlaced = interlaced;
    std::uniform_int_distribution<unsigned> sample(0, (1u << depth) - 1);
    s.samples.resize(size_t(s.width * s.height * channels));
    for (unsigned& v : s.samples) v = sample(random);
    return s;
  };
  std::vector<std::pair<std::string, PngSpec>> files = {
      {"grey1", spec(PNG_COLOR_TYPE_GRAY, 1, 1)},
      {"grey4", spec(PNG_COLOR_TYPE_GRAY, 4, 1)},
      {"grey8", spec(PNG_COLOR_TYPE_GRAY, 8, 1)},
      {"grey16", spec(PNG_COLOR_TYPE_GRAY, 16, 1)},
      {"grey_alpha8", spec(PNG_COLOR_TYPE_GRAY_ALPHA, 8, 2)},
      {"grey_alpha16", spec(PNG_COLOR_TYPE_GRAY_ALPHA, 16, 2)},
      {"rgb8", spec(PNG_COLOR_TYPE_RGB, 8, 3)},
      {"rgb16", spec(PNG_COLOR_TYPE_RGB, 16, 3)},
      {"rgba8", spec(PNG_COLOR_TYPE_RGB_ALPHA, 8, 4)},
      {"rgba16", spec(PNG_COLOR_TYPE_RGB_ALPHA, 16, 4)},
      {"rgba8_interlaced", spec(PNG_COLOR_TYPE_RGB_ALPHA, 8, 4, true)},
      {"palette4", spec(PNG_COLOR_TYPE_PALETTE, 4, 1)},
      {"palette8_transparent", spec(PNG_COLOR_TYPE_PALETTE, 8, 1)},
      {"rgba8_gamma2.2", spec(PNG_COLOR_TYPE_RGB_ALPHA, 8, 4)},
      {"rgba8_gamma0.6", spec(PNG_COLOR_TYPE_RGB_ALPHA, 8, 4)},
      {"grey_alpha16_gamma1.8", spec(PNG_COLOR_TYPE_GRAY_ALPHA, 16, 2)},
      {"rgba8_gamma_and_srgb", spec(PNG_COLOR_TYPE_RGB_ALPHA, 8, 4)}};
  // Alpha is associated in linear light under a gAMA chunk, unless an sRGB chunk overrides it.
  for (auto& [name, s] : files) {
    if (name.find("srgb") != std::string::npos)
      s.file_gamma = 0.45455, s.srgb = true;
    else if (const size_t at = name.find("gamma"); at != std::string::npos)
      s.file_gamma = 1.0 / std::stod(name.substr(at + 5));
    if (s.colour_type != PNG_COLOR_TYPE_PALETTE) continue;
    for (int i = 0; i < (1 << s.depth); ++i)
      s.palette.push_back({png_byte(random() % 256), png_byte(random() % 256), png_byte(random() % 256)});
    if (name.find("transparent") != std::string::npos)
      for (int i = 0; i < 100; ++i) s.transparency.push_back(png_byte(random() % 256));
  }
  for (const auto& [name, s] : files) {
    const std::string path = dir.file(name + ".png");
    write_spec(path, s);
    ASSERT_TRUE(is_png_file(path)) << name;
    expect_same_image(read_image(path), read_by_openimageio(path), name);
    std::vector<std::string> names;
    ASSERT_EQ(openimageio_files(path).channel_names(path, names), "");
    EXPECT_EQ(read_channel_names(path), names) << name;
  }
}

// A PNG of its signature, header and an empty data chunk: `width` × `height` RGBA pixels of 16 bits.
bool write_header_rows(png_structp png, png_infop info, std::FILE* file, int width, int height) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, file);
  png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 16, PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  // An empty data chunk, where a reader's look at the header ends.
  png_write_chunk(png, reinterpret_cast<png_const_bytep>("IDAT"), nullptr, 0);
  return true;
}

void write_header_only(const std::string& path, int width, int height) {
  write_png_file(path, [&](png_structp png, png_infop info, std::FILE* file) {
    return write_header_rows(png, info, file, width, height);
  });
}

TEST(PngFile, ADamagedPngIsAnErrorNamingTheFile) {
  test::TempDir dir;
  const std::string whole = dir.file("whole.png"), cut = dir.file("cut.png");
  write_image(whole, row_image(testing_values(3, true), 3));
  std::ifstream in(whole, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  std::ofstream(cut, std::ios::binary) << bytes.str().substr(0, bytes.str().size() / 2);
  try {
    read_image(cut);
    FAIL() << "read a truncated PNG";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(cut + ": cannot read the image data (", 0), 0u) << e.what();
  }
  // A header that asks for 100,000 × 100,000 pixels is refused before anything is allocated for them.
  const std::string huge = dir.file("huge.png");
  write_header_only(huge, 100000, 100000);
  try {
    read_image(huge);
    FAIL() << "read a PNG of 10^10 pixels";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              huge +
                  ": cannot read the image data (100000 x 100000 pixels of 4 channels: more than the 2^30 "
                  "values gpsurf reads)");
  }
  Image five;
  five.width = five.height = 1;
  five.channels = 5;
  five.pixels.assign(5, 0.5f);
  EXPECT_THROW(write_image(dir.file("five.png"), five), Error);
  EXPECT_FALSE(std::filesystem::exists(dir.file("five.png")));
}

TEST(ImageFiles, AnExrKeepsItsChannelNamesAndFloats) {
  test::TempDir dir;
  const Image image = row_image(testing_values(4, false), 4);
  write_image(dir.file("a.exr"), image, {"P.X", "P.Y", "P.Z", "P.coverage"});
  const Image exr = read_image(dir.file("a.exr"));
  EXPECT_EQ(read_channel_names(dir.file("a.exr")), (std::vector<std::string>{"P.X", "P.Y", "P.Z", "P.coverage"}));
  ASSERT_EQ(exr.pixels.size(), image.pixels.size());
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    if (!std::isfinite(image.pixels[i])) continue;
    EXPECT_EQ(exr.pixels[i], image.pixels[i]) << i;
  }
}

}  // namespace
}  // namespace gps
