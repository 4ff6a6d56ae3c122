#pragma once
// A MatCap as users name it: a built-in one, or an image file (image_io.h).
#include <string>

#include "render/image/image.h"

namespace gps {

/// A built-in MatCap by name, or an image file (PNG, EXR, ...).
/// An unknown name that is not a file is a usage error listing the names.
Image load_matcap(const std::string& name_or_file);

}  // namespace gps
