#pragma once
// Small line plots as PNG (benchmark figures like thesis Figs. 4.6 and 4.7), drawn with OpenImageIO in
// the image module (image_file_module.h).
#include <string>
#include <utility>
#include <vector>

namespace gps {

struct PlotSeries {
  std::string name;
  std::vector<std::pair<double, double>> points;  // (x, y), drawn in order
};

/// Writes a plot with axes, ticks at the data's range ends, a legend, and logarithmic axes where asked.
void write_line_plot(const std::string& path, const std::string& title, const std::string& x_label,
                     const std::string& y_label, const std::vector<PlotSeries>& series, bool log_x, bool log_y);

}  // namespace gps
