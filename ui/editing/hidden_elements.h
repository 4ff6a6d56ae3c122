#pragma once
// Hide and reveal, as Blender's edit mode (H, Shift+H, Alt+H): faces and vertices kept out of the
// view, of picking and of selecting. An edge is hidden with an end, or with every face beside it.
// A view state only: never saved, and no part of the surface's math (GPS subdivision is global: the
// visible faces still show the limit surface of the whole mesh; hiding only skips drawing them).
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "ui/editing/selection.h"

namespace gps {

class HiddenElements {
public:
  bool empty() const { return faces_.empty() && vertices_.empty(); }
  /// The hidden faces and vertices, ascending.
  const std::vector<int>& faces() const { return faces_; }
  const std::vector<int>& vertices() const { return vertices_; }
  bool face_hidden(int face) const;
  bool vertex_hidden(int vertex) const;
  /// Whether the edge {a, b} of `mesh` is hidden: an end is, or every face beside it.
  bool edge_hidden(const CovarianceMesh& mesh, int a, int b) const;

  /// Per vertex, per face and per edge (by its index in `mesh`): 1 where hidden (for picking).
  std::vector<char> vertex_mask(size_t n_vertices) const;
  std::vector<char> face_mask(size_t n_faces) const;
  std::vector<char> edge_mask(const CovarianceMesh& mesh) const;
  /// The vertices of `vertices` that are not hidden (same order).
  std::vector<int> shown(const std::vector<int>& vertices) const;
  /// The hidden edges of `mesh`, as (min, max), ascending.
  std::vector<EdgeEnds> edges(const CovarianceMesh& mesh) const;

  /// H, or Shift+H where `unselected`: hides what the selection holds in `mode` (what it does not
  /// hold) with what uses it. Vertex mode: the vertices and the faces around them; edge mode: the
  /// faces beside the edges; face mode: the faces. In edge and face mode a vertex is hidden with its
  /// last face. What is hidden leaves the selection. Returns the number of faces newly hidden.
  size_t hide(const CovarianceMesh& mesh, Selection& selection, SelectMode mode, bool unselected);
  /// Alt+H: shows everything and adds what was hidden to the selection (its vertices, edges or
  /// faces, by `mode`). Returns the number of faces shown.
  size_t reveal(const CovarianceMesh& mesh, Selection& selection, SelectMode mode);
  /// Takes the hidden elements out of `selection` (after a command that selects, e.g. select all).
  void deselect_hidden(const CovarianceMesh& mesh, Selection& selection, SelectMode mode) const;
  /// Whether the hidden indices are of `mesh`: nothing is hidden, or its faces have the corners they
  /// had when hiding (an operation that kept the topology, as a crease, keeps what is hidden).
  bool fits(const CovarianceMesh& mesh) const;
  /// Shows everything, selecting nothing (the topology changed: the indices are another mesh's).
  void clear() {
    faces_.clear();
    vertices_.clear();
    topology_.clear();
  }

private:
  std::vector<int> faces_, vertices_;
  std::vector<int> topology_;  // of the mesh hidden in: each face's corner count, then its corners
};

}  // namespace gps
