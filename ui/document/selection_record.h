#pragma once
// A selection as the undo history keeps it with a mesh: its vertices and, where it held edges of its
// own (edge mode), those edges, so that an undo gives back the edges and not every edge between
// their ends.
#include <array>
#include <vector>

namespace gps {

struct SelectionRecord {
  std::vector<int> vertices;
  std::vector<std::array<int, 2>> edges;  // (min, max), ascending; where holds_edges
  bool holds_edges = false;
  bool operator==(const SelectionRecord&) const = default;
};

}  // namespace gps
