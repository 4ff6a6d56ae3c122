#pragma once
// The editor's selection: click, shift-click to add or remove, box select, all, none. As in Blender's
// edit mode it is a set of vertices, in edge mode a set of edges as well and in face mode a set of
// faces: there a click, a box or a loop selects edges or faces (their vertices too), so that the edges
// between two selected edges' ends, or a face whose corners all lie on selected faces, are not
// selected with them. Otherwise an edge is selected when both its ends are, a face when all its
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
/// A face by its corners, ascending (an index would not survive the renumbering of an undo).
using FaceCorners = std::vector<int>;

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

  /// Whether it holds faces of its own (face mode), else its faces are those with all corners selected.
  bool holds_faces() const { return holds_faces_; }
  /// The face last clicked alone in face mode, where it is still held and a face of `mesh`; else −1.
  /// Where a shortest path of faces starts (Ctrl+click).
  int active_face(const CovarianceMesh& mesh) const;
  /// Makes a held face the active one (nothing where it is not held).
  void set_active_face(const CovarianceMesh& mesh, int face);
  /// The selected faces, ascending: those held that are still faces of `mesh`, else every face of
  /// `mesh` whose corners are all selected.
  std::vector<int> faces(const CovarianceMesh& mesh) const;

  // Selecting vertices (or a face's corners): the edges are again those with both ends selected,
  // the faces those with all corners selected.

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

  // Selecting faces (face mode): the selection holds faces of `mesh`, and the vertices are their corners.

  /// A click on a face (`faces` of one) or a face loop, `active` the vertex the inspector shows. Plain:
  /// select only them (none: clear); toggle: remove them when all are selected, else add them. A face
  /// clicked alone becomes the active face.
  void click_faces(const CovarianceMesh& mesh, const std::vector<int>& faces, int active, bool toggle);
  /// Box select in face mode: replace the selection by `faces`, or add them (additive).
  void select_faces(const CovarianceMesh& mesh, const std::vector<int>& faces, bool additive);
  /// Removes `faces` from the selected faces.
  void deselect_faces(const CovarianceMesh& mesh, const std::vector<int>& faces);
  /// Selects exactly the faces of `mesh` not selected now.
  void invert_faces(const CovarianceMesh& mesh);
  /// Into face mode, as Blender converts: holds the faces whose corners are all selected, and only
  /// their corners. Nothing changes where it holds faces already.
  void hold_faces(const CovarianceMesh& mesh);
  /// As `mode` selects: the edges (edge mode) or faces (face mode) among the selected vertices held
  /// where none are held yet (hold_edges, hold_faces); in vertex mode neither held, the vertices kept.
  void hold_for(SelectMode mode, const CovarianceMesh& mesh);
  /// Out of face mode: the vertices stay (the held faces' corners).
  void release_faces() {
    faces_.clear();
    holds_faces_ = false;
  }

  // As the undo history keeps it.

  /// The vertices and the edges or faces held, the active vertex left out.
  SelectionRecord record() const { return {vertices_, edges_, holds_edges_, faces_, holds_faces_}; }
  /// Selects exactly what `record` holds (its edges or faces held where it held them).
  void restore(const SelectionRecord& record);

private:
  void set_edges(std::vector<EdgeEnds> edges);
  void set_faces(std::vector<FaceCorners> faces);  // each face's corners ascending (corner_sets)
  // The faces' corner sets, ascending.
  static std::vector<FaceCorners> corner_sets(const CovarianceMesh& mesh, const std::vector<int>& faces);
  // The face of `mesh` with these corners (ascending), or −1.
  static int face_with_corners(const CovarianceMesh& mesh, const FaceCorners& corners);
  // Vertices selected as vertices: neither edges nor faces held.
  void release() {
    release_edges();
    release_faces();
  }

  std::vector<int> vertices_;
  std::vector<EdgeEnds> edges_;  // ascending, where holds_edges_
  bool holds_edges_ = false;
  std::vector<FaceCorners> faces_;  // ascending, where holds_faces_
  bool holds_faces_ = false;
  FaceCorners active_face_;  // the corners of the face last clicked alone
  int last_clicked_ = -1;
};

/// The vertices whose means project inside the window-pixel rectangle spanned by `a` and `b` (any
/// two opposite corners), in front of the camera; hidden ones too (box selection selects through).
std::vector<int> vertices_in_box(const Camera& camera, int width, int height, glm::vec2 a, glm::vec2 b,
                                 const CovarianceMesh& mesh);

}  // namespace gps
