#include "render/image/line_plot_drawing.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace gps {

namespace {
// Debian's fonts-dejavu-core (scripts/install_deps.sh); without it the plot has no text.
constexpr const char* kFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr float kColors[][3] = {{0.85f, 0.33f, 0.10f}, {0.00f, 0.45f, 0.74f}, {0.47f, 0.67f, 0.19f},
                                {0.49f, 0.18f, 0.56f}, {0.93f, 0.69f, 0.13f}, {0.30f, 0.75f, 0.93f}};

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}
}  // namespace

std::string draw_line_plot(const std::string& path, const std::string& title, const std::string& x_label,
                           const std::string& y_label, const std::vector<PlotSeries>& series, bool log_x, bool log_y) {
  const int width = 720, height = 480, left = 90, right = 170, top = 40, bottom = 60;
  OIIO::ImageBuf image(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT));
  const float white[3] = {1, 1, 1}, black[3] = {0, 0, 0}, grey[3] = {0.6f, 0.6f, 0.6f};
  OIIO::ImageBufAlgo::fill(image, white);
  const auto tx = [&](double x) { return log_x ? std::log10(std::max(x, 1e-30)) : x; };
  const auto ty = [&](double y) { return log_y ? std::log10(std::max(y, 1e-30)) : y; };
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300, raw_x0 = 0, raw_x1 = 0, raw_y0 = 0, raw_y1 = 0;
  for (const auto& s : series)
    for (const auto& [x, y] : s.points) {
      if (tx(x) < x0) x0 = tx(x), raw_x0 = x;
      if (tx(x) > x1) x1 = tx(x), raw_x1 = x;
      if (ty(y) < y0) y0 = ty(y), raw_y0 = y;
      if (ty(y) > y1) y1 = ty(y), raw_y1 = y;
    }
  if (x1 <= x0) x1 = x0 + 1;
  if (y1 <= y0) y1 = y0 + 1;
  const auto px = [&](double x) { return left + int((tx(x) - x0) / (x1 - x0) * (width - left - right)); };
  const auto py = [&](double y) { return height - bottom - int((ty(y) - y0) / (y1 - y0) * (height - top - bottom)); };
  OIIO::ImageBufAlgo::render_box(image, left, top, width - right, height - bottom, grey);
  const bool font = std::filesystem::exists(kFont);
  const auto text = [&](int x, int y, const std::string& s, int size = 14) {
    if (font) OIIO::ImageBufAlgo::render_text(image, x, y, s, size, kFont, black);
  };
  text(left, top - 14, title, 18);
  text((left + width - right) / 2 - 40, height - 15, x_label + (log_x ? " (log)" : ""));
  text(8, top - 14 + 0, "", 14);
  text(4, height / 2, y_label + (log_y ? " (log)" : ""), 13);
  text(left - 4, height - bottom + 18, number(raw_x0));
  text(width - right - 30, height - bottom + 18, number(raw_x1));
  text(left - 60, height - bottom, number(raw_y0));
  text(left - 60, top + 10, number(raw_y1));
  for (size_t k = 0; k < series.size(); ++k) {
    const float* c = kColors[k % 6];
    const auto& pts = series[k].points;
    for (size_t i = 0; i + 1 < pts.size(); ++i)
      OIIO::ImageBufAlgo::render_line(image, px(pts[i].first), py(pts[i].second), px(pts[i + 1].first),
                                      py(pts[i + 1].second), {c, 3});
    for (const auto& [x, y] : pts)
      OIIO::ImageBufAlgo::render_box(image, px(x) - 2, py(y) - 2, px(x) + 2, py(y) + 2, {c, 3}, true);
    const int ly = top + 20 + 22 * int(k);
    OIIO::ImageBufAlgo::render_box(image, width - right + 12, ly - 8, width - right + 24, ly + 2, {c, 3}, true);
    text(width - right + 30, ly + 2, series[k].name);
  }
  const std::string temp = path + ".tmp.png";
  if (!image.write(temp)) return path + ": cannot write the plot";
  std::error_code ec;
  std::filesystem::rename(temp, path, ec);
  if (ec) return path + ": cannot replace the file (" + ec.message() + ")";
  return "";
}

}  // namespace gps
