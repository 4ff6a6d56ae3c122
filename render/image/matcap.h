#pragma once
// MatCaps (thesis 4.1): a sphere's shaded image indexed by the view-space normal.
#include <string>
#include <vector>

#include "render/image/image.h"

namespace gps {

/// The MatCaps gpsurf makes itself, by name.
std::vector<std::string> builtin_matcap_names();

/// A built-in MatCap rendered procedurally (a lit sphere), size × size RGB.
Image make_builtin_matcap(const std::string& name, int size = 256);

}  // namespace gps
