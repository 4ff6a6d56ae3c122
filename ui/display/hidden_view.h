#pragma once
// What is hidden (H, Shift+H, Alt+H) as the window needs it: the hidden elements
// (ui/editing/hidden_elements.h), their masks over the document's vertices, edges and faces, which
// picking and selecting skip, and the shown surface's patches and cage edges the frame leaves out.
// It follows the shown surface's topology revision; a change of what is hidden refreshes it at once.
#include <cstdint>
#include <string>
#include <vector>

#include "ui/display/shown_surface.h"
#include "ui/editing/hidden_elements.h"

namespace gps {

class HiddenView {
public:
  HiddenElements& elements() { return elements_; }
  const HiddenElements& elements() const { return elements_; }

  /// The masks and the patches left out again, for `document` as `shown` draws it (a preview, another
  /// mesh, is drawn whole). Returns why no patch is left out where they cannot be found ("": none).
  std::string refresh(const CovarianceMesh& document, const ShownSurface& shown);
  /// refresh() where the shown surface's topology changed since the last one, else nothing ("").
  std::string follow(const CovarianceMesh& document, const ShownSurface& shown) {
    return shown.topology_changed_since(seen_) ? refresh(document, shown) : std::string();
  }

  /// 1 per hidden vertex, edge (in the mesh's edge order) and face of the document; empty where
  /// nothing is hidden.
  const std::vector<char>& vertex_mask() const { return vertex_mask_; }
  const std::vector<char>& edge_mask() const { return edge_mask_; }
  const std::vector<char>& face_mask() const { return face_mask_; }
  /// What the frame leaves out of the mesh shown: its patches, and its cage's edges (1 per edge).
  const std::vector<int>& patches() const { return patches_; }
  const std::vector<char>& cage_edges() const { return cage_edges_; }

private:
  HiddenElements elements_;
  std::vector<char> vertex_mask_, edge_mask_, face_mask_, cage_edges_;
  std::vector<int> patches_;
  std::uint64_t seen_ = 0;  // the shown surface's topology revision refreshed for
};

}  // namespace gps
