#include "ui/display/hidden_view.h"

#include "core/plans/patch_faces.h"
#include "core/support/error.h"

namespace gps {

std::string HiddenView::refresh(const CovarianceMesh& document, const ShownSurface& shown) {
  seen_ = shown.topology_revision();
  patches_.clear();
  cage_edges_.clear();
  vertex_mask_.clear();
  edge_mask_.clear();
  face_mask_.clear();
  if (elements_.empty()) return "";
  vertex_mask_ = elements_.vertex_mask(document.n_vertices());
  edge_mask_ = elements_.edge_mask(document);
  face_mask_ = elements_.face_mask(document.n_faces());
  if (shown.preview()) return "";  // a modal tool's preview, another mesh, is drawn whole
  // With the mirror modifier, the half's faces and vertices keep their indices in the mesh shown
  // (core/modelling/mirror.h): its mirror image stays drawn.
  const CovarianceMesh& drawn = shown.drawn(document);
  std::string refusal;
  try {
    patches_ = patches_of_faces(drawn.topology(), shown.renderer().tables().plans, elements_.faces());
  } catch (const Error& e) {  // not the renderer's mesh: nothing is left out rather than the wrong patches
    refusal = e.what();
  }
  cage_edges_ = elements_.edge_mask(drawn);
  return refusal;
}

}  // namespace gps
