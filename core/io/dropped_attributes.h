#pragma once
// What a mesh file holds that a covariance mesh does not keep (texture coordinates, normals, vertex
// colours), counted by the readers so that dropping them is said, not silent.
#include <cstddef>
#include <string>
#include <vector>

namespace gps {

struct DroppedAttributes {
  size_t texture_coordinates = 0, normals = 0, colours = 0;
  /// Other properties not read, as "vertex property quality" or "face properties red, green and blue".
  std::vector<std::string> other;

  bool empty() const { return texture_coordinates == 0 && normals == 0 && colours == 0 && other.empty(); }
};

/// A PLY vertex element's properties (`names`, `count` records) that the reader does not read, into
/// `dropped`: normals, colours and texture coordinates counted by the property that leads each (nx;
/// red, diffuse_red; u, s, texture_u, texture_s), any other named, also one of theirs without its lead
/// (a lone v, alpha beside normals).
void count_unread_vertex_properties(const std::vector<std::string>& names, size_t count, DroppedAttributes& dropped);

/// How many names a note lists at most: a file's thousands of names would make a line of thousands.
inline constexpr size_t kNamesListed = 8;
/// "ONE A" or "MANY A, B and C" ("vertex property 'q'", "the tags 'holes' and 'x'"), past kNamesListed
/// names the first ones and "and N more"; "" for no names.
std::string named_list(const std::string& one, const std::string& many, const std::vector<std::string>& names);

/// "SOURCE: 4 texture coordinates, 1 normal and 4 vertex colours dropped (a covariance mesh keeps
/// positions, Gaussians and creases; normals come from the limit surface)"; "" where none were.
std::string dropped_attributes_note(const std::string& source, const DroppedAttributes& dropped);

}  // namespace gps
