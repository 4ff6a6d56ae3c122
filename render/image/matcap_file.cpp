#include "render/image/matcap_file.h"

#include <algorithm>
#include <filesystem>

#include "core/support/error.h"
#include "render/image/image_io.h"
#include "render/image/matcap.h"

namespace gps {

Image load_matcap(const std::string& name_or_file) {
  const auto names = builtin_matcap_names();
  if (std::find(names.begin(), names.end(), name_or_file) != names.end()) return make_builtin_matcap(name_or_file);
  std::error_code ec;
  if (!std::filesystem::exists(name_or_file, ec)) {
    std::string known;
    for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
    throw usage_error("unknown MatCap '" + name_or_file + "' (neither a file nor one of: " + known + ")");
  }
  Image image = read_image(name_or_file);
  if (image.channels < 3) throw Error(name_or_file + ": a MatCap needs an RGB image");
  return image;
}

}  // namespace gps
