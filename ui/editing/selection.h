#pragma once
// The editor's vertex selection: click, shift-click to add or remove, box select, all, none. As in
// Blender's edit mode the selection is a set of vertices in every selection mode: an edge is
// selected when both its ends are, a face when all its corners are.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh/covariance_mesh.h"
#include "view/camera.h"

namespace gps {

/// What a click picks: the nearest vertex, the nearest edge (its two ends) or the face under the
/// cursor (its corners).
enum class SelectMode { vertex, edge, face };
/// "vertex", "edge", "face".
std::string select_mode_name(SelectMode mode);

class Selection {
public:
  /// The selected vertices, ascending.
  const std::vector<int>& vertices() const { return vertices_; }
  bool empty() const { return vertices_.empty(); }
  bool contains(int vertex) const;
  /// The vertex the inspector shows: the one last clicked if still selected, else the first; −1 if none.
  int active() const;

  /// A click on `vertex` (−1: on nothing). Plain: select only it (nothing: clear). Toggle (shift):
  /// add it, or remove it if selected (nothing: keep the selection).
  void click(int vertex, bool toggle);
  /// A click on an edge or a face: `group` its vertices, `active` the one the inspector shows. Plain:
  /// select only the group; toggle: remove the group when all of it is selected, else add it.
  void click_group(const std::vector<int>& group, int active, bool toggle);
  /// Box select: replace the selection by `inside`, or add them (additive).
  void select(const std::vector<int>& inside, bool additive);
  /// Removes `outside` from the selection.
  void deselect(const std::vector<int>& outside);
  /// Selects exactly the vertices not selected now.
  void invert(size_t n_vertices);
  void select_all(size_t n_vertices);
  void clear();

private:
  std::vector<int> vertices_;
  int last_clicked_ = -1;
};

/// The vertices whose means project inside the window-pixel rectangle spanned by `a` and `b` (any
/// two opposite corners), in front of the camera; hidden ones too (box selection selects through).
std::vector<int> vertices_in_box(const Camera& camera, int width, int height, glm::vec2 a, glm::vec2 b,
                                 const CovarianceMesh& mesh);

}  // namespace gps
