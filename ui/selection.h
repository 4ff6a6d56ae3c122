#pragma once
// The editor's vertex selection: click, shift-click to add or remove, box select, all, none.
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh/covariance_mesh.h"
#include "view/camera.h"

namespace gps {

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
  /// Box select: replace the selection by `inside`, or add them (additive).
  void select(const std::vector<int>& inside, bool additive);
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
