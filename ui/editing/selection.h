#pragma once
// The editor's selection: click, shift-click to add or remove, box select, all, none. As in Blender's
// edit mode it is a set of vertices, and in edge mode a set of edges as well: there a click, a box
// or a loop selects edges (their ends too), so that the edges between two selected edges' ends are
// not selected with them. Otherwise an edge is selected when both its ends are, a face when all its
// corners are.
#include <array>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh/covariance_mesh.h"
#include "ui/document/selection_record.h"
#include "view/camera.h"

namespace gps {

/// What a click picks: the nearest vertex, the nearest edge or the face under the cursor (its corners).
enum class SelectMode { vertex, edge, face };
/// "vertex", "edge", "face".
std::string select_mode_name(SelectMode mode);

/// An edge by its ends, (min, max).
using EdgeEnds = std::array<int, 2>;

class Selection {
public:
  /// The selected vertices, ascending (in edge mode the selected edges' ends).
  const std::vector<int>& vertices() const { return vertices_; }
  bool empty() const { return vertices_.empty(); }
  bool contains(int vertex) const;
  /// The vertex the inspector shows: the one last clicked if still selected, else the first; −1 if none.
  int active() const;
  /// Makes a selected vertex the active one (nothing where it is not selected).
  void set_active(int vertex) {
    if (contains(vertex)) last_clicked_ = vertex;
  }

  /// Whether it holds edges of its own (edge mode), else its edges are those with both ends selected.
  bool holds_edges() const { return holds_edges_; }
  /// The selected edges, ascending: those held that are still edges of `mesh`, else every edge of
  /// `mesh` with both ends selected.
  std::vector<EdgeEnds> edges(const CovarianceMesh& mesh) const;

  // Selecting vertices (or a face's corners): the edges are again those with both ends selected.

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

  // Selecting edges (edge mode): the selection holds edges, and the vertices are their ends.

  /// A click on an edge (`group` of one) or an edge loop, `active` the vertex the inspector shows.
  /// Plain: select only the group (none: clear); toggle: remove the group when all of it is
  /// selected, else add it.
  void click_edges(const CovarianceMesh& mesh, const std::vector<EdgeEnds>& group, int active, bool toggle);
  /// Box select in edge mode: replace the selection by `inside`, or add them (additive).
  void select_edges(const CovarianceMesh& mesh, const std::vector<EdgeEnds>& inside, bool additive);
  /// Removes `outside` from the selected edges.
  void deselect_edges(const CovarianceMesh& mesh, const std::vector<EdgeEnds>& outside);
  /// Selects exactly the edges of `mesh` not selected now.
  void invert_edges(const CovarianceMesh& mesh);
  /// Into edge mode, as Blender converts: holds the edges with both ends selected, and only their
  /// ends (a vertex on no selected edge is let go). Nothing changes where it holds edges already.
  void hold_edges(const CovarianceMesh& mesh);
  /// Out of edge mode: the vertices stay (the held edges' ends); the edges are again those with
  /// both ends selected.
  void release_edges() {
    edges_.clear();
    holds_edges_ = false;
  }

  // As the undo history keeps it.

  /// The vertices and the edges held, the active vertex left out.
  SelectionRecord record() const { return {vertices_, edges_, holds_edges_}; }
  /// Selects exactly what `record` holds (its edges held where it held them).
  void restore(const SelectionRecord& record);

private:
  void set_edges(std::vector<EdgeEnds> edges);

  std::vector<int> vertices_;
  std::vector<EdgeEnds> edges_;  // ascending, where holds_edges_
  bool holds_edges_ = false;
  int last_clicked_ = -1;
};

/// The vertices whose means project inside the window-pixel rectangle spanned by `a` and `b` (any
/// two opposite corners), in front of the camera; hidden ones too (box selection selects through).
std::vector<int> vertices_in_box(const Camera& camera, int width, int height, glm::vec2 a, glm::vec2 b,
                                 const CovarianceMesh& mesh);

}  // namespace gps
