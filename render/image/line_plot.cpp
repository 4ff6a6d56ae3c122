#include "render/image/line_plot.h"

#include "core/support/error.h"
#include "render/image/image_file_module.h"

namespace gps {

void write_line_plot(const std::string& path, const std::string& title, const std::string& x_label,
                     const std::string& y_label, const std::vector<PlotSeries>& series, bool log_x, bool log_y) {
  if (const std::string failure = openimageio_files(path + ": cannot write the plot")
                                      .line_plot(path, title, x_label, y_label, series, log_x, log_y);
      !failure.empty())
    throw Error(failure);
}

}  // namespace gps
