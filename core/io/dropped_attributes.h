#pragma once
// What a mesh file holds that a covariance mesh does not keep (texture coordinates, normals, vertex
// colours), counted by the readers so that dropping them is said, not silent.
#include <cstddef>
#include <string>

namespace gps {

struct DroppedAttributes {
  size_t texture_coordinates = 0, normals = 0, colours = 0;

  bool empty() const { return texture_coordinates == 0 && normals == 0 && colours == 0; }
};

/// "SOURCE: 4 texture coordinates, 1 normal and 4 vertex colours dropped (a covariance mesh keeps
/// positions, Gaussians and creases; normals come from the limit surface)"; "" where none were.
std::string dropped_attributes_note(const std::string& source, const DroppedAttributes& dropped);

}  // namespace gps
