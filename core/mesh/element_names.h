#pragma once
// How a message names a mesh's vertices and faces: by index from 0 ("vertex 3", "face 0") unless the
// file it was read from numbers them otherwise (an OBJ file from 1, with each element's line), which
// its reader supplies, so that every message about one file numbers its elements the same way.
#include <functional>
#include <string>
#include <utility>

#include "core/support/error.h"

namespace gps {

struct ElementNames {
  std::function<std::string(int)> vertex_name, face_name;  // empty: by index from 0

  std::string vertex(int v) const { return vertex_name ? vertex_name(v) : "vertex " + std::to_string(v); }
  std::string face(int f) const { return face_name ? face_name(f) : "face " + std::to_string(f); }
};

/// An error about one vertex or face of a mesh, found where the mesh's file is not known (the plans):
/// its message numbers the element from 0 until whoever read the file names it as the file does.
class ElementError : public Error {
public:
  enum class Element { vertex, face };
  /// The message `before` + the element's name + `after`.
  ElementError(Element element, int index, std::string before, std::string after, Kind kind = Kind::runtime)
      : Error(before + (element == Element::face ? ElementNames{}.face(index) : ElementNames{}.vertex(index)) + after,
              kind),
        element_(element),
        index_(index),
        before_(std::move(before)),
        after_(std::move(after)) {}
  /// The message with the element named by `names`.
  std::string named(const ElementNames& names) const {
    return before_ + (element_ == Element::face ? names.face(index_) : names.vertex(index_)) + after_;
  }

private:
  Element element_;
  int index_;
  std::string before_, after_;
};

}  // namespace gps
