#include "core/io/dropped_attributes.h"

#include <vector>

namespace gps {

std::string dropped_attributes_note(const std::string& source, const DroppedAttributes& dropped) {
  std::vector<std::string> parts;
  const auto count = [&](size_t n, const char* one, const char* many) {
    if (n > 0) parts.push_back(std::to_string(n) + " " + (n == 1 ? one : many));
  };
  count(dropped.texture_coordinates, "texture coordinate", "texture coordinates");
  count(dropped.normals, "normal", "normals");
  count(dropped.colours, "vertex colour", "vertex colours");
  if (parts.empty()) return "";
  std::string listed = parts[0];
  for (size_t k = 1; k < parts.size(); ++k) listed += (k + 1 == parts.size() ? " and " : ", ") + parts[k];
  return source + ": " + listed +
         " dropped (a covariance mesh keeps positions, Gaussians and creases; normals come from the limit surface)";
}

}  // namespace gps
