#pragma once
// How a message names a mesh's vertices and faces: by index from 0 ("vertex 3", "face 0") unless the
// file it was read from numbers them otherwise (an OBJ file from 1, with each element's line), which
// its reader supplies, so that every message about one file numbers its elements the same way.
#include <functional>
#include <string>

namespace gps {

struct ElementNames {
  std::function<std::string(int)> vertex_name, face_name;  // empty: by index from 0

  std::string vertex(int v) const { return vertex_name ? vertex_name(v) : "vertex " + std::to_string(v); }
  std::string face(int f) const { return face_name ? face_name(f) : "face " + std::to_string(f); }
};

}  // namespace gps
