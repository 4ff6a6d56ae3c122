#pragma once
// The drawing of line_plot.h's plots with OpenImageIO's ImageBufAlgo, in the image module
// (image_file_module.h).
#include <string>
#include <vector>

#include "render/image/line_plot.h"

namespace gps {

/// write_line_plot's work; returns "" or the one-line message of its failure.
std::string draw_line_plot(const std::string& path, const std::string& title, const std::string& x_label,
                           const std::string& y_label, const std::vector<PlotSeries>& series, bool log_x, bool log_y);

}  // namespace gps
