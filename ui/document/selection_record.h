#pragma once
// A selection as the undo history keeps it with a mesh: its vertices and, where it held edges or faces
// of its own (edge or face mode), those, so that an undo gives back the edges and not every edge
// between their ends, the faces and not every face among their corners.
#include <array>
#include <vector>

namespace gps {

struct SelectionRecord {
  std::vector<int> vertices;
  std::vector<std::array<int, 2>> edges;  // (min, max), ascending; where holds_edges
  bool holds_edges = false;
  std::vector<std::vector<int>> faces;  // each face's corners ascending, the faces ascending; where holds_faces
  bool holds_faces = false;
  bool operator==(const SelectionRecord&) const = default;
};

}  // namespace gps
