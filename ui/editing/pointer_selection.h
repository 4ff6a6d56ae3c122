#pragma once
// Selecting with the pointer in Blender's three modes, without a window: a click picks a vertex, an
// edge or a face; Alt+click a loop, Ctrl+Alt+click a ring, Ctrl+click a shortest path; a box takes
// what the camera sees (everything with X-ray). Hidden elements are never picked. Each call changes
// the selection it is given and returns what the status line says of it (nothing where empty).
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh/covariance_mesh.h"
#include "ui/editing/hidden_elements.h"
#include "ui/editing/selection.h"
#include "view/projection.h"

namespace gps {

/// What the pointer selects in: the view, the mesh, the mode, and 1 per hidden vertex, edge (in the
/// mesh's edge order) and face, or empty where nothing is hidden; `through` (X-ray): elements the
/// surface hides are picked too.
struct PointerScene {
  const Viewport& view;
  const CovarianceMesh& mesh;
  SelectMode mode;
  const std::vector<char>& hidden_vertices;
  const std::vector<char>& hidden_edges;
  const std::vector<char>& hidden_faces;
  bool through = false;
};

/// A status line: what a selection did, or why it did nothing.
struct SelectionNote {
  std::string text;
  bool error = false;
};

/// 1 per vertex a click cannot pick: hidden, or (without X-ray) not seen by the camera
/// (view/visible_vertices.h), as Blender's solid mode picks what is in front.
std::vector<char> unpickable_vertices(const PointerScene& scene);
/// The vertex nearest `pixel` within `radius` window pixels that a click can pick (not one of
/// unpickable_vertices); −1 where none is.
int pick_visible_vertex(const PointerScene& scene, glm::vec2 pixel, float radius);

/// The element under `pixel` in the mode, as its vertices (a face where no vertex or edge is near).
std::vector<int> vertices_under(const PointerScene& scene, glm::vec2 pixel);
/// A click: in vertex mode `vertex` (the vertex or ellipsoid picked there, −1 none); else the edge or
/// face under `pixel`. `toggle` (Shift) adds or removes it.
void click_select(Selection& selection, const PointerScene& scene, glm::vec2 pixel, int vertex, bool toggle);
/// Alt+click: the edge loop through the edge under `pixel` (its edges, its vertices, or in face mode
/// the loop of faces across it).
SelectionNote loop_select(Selection& selection, const PointerScene& scene, glm::vec2 pixel, bool toggle);
/// Ctrl+Alt+click: the ring a loop cut through the edge would cross: its edges in edge mode, their
/// ends in vertex mode; in face mode the faces between them, as Blender's ring selects a loop there.
SelectionNote ring_select(Selection& selection, const PointerScene& scene, glm::vec2 pixel, bool toggle);
/// Ctrl+click: adds the shortest path along the edges from the active vertex to `vertex` (picked
/// under `pixel`), which becomes the active one; in edge mode the path's edges; in face mode the faces
/// from the active face to the face under `pixel`. With nothing to start from it is a plain click.
SelectionNote path_select(Selection& selection, const PointerScene& scene, glm::vec2 pixel, int vertex);
/// A box from `a` to `b`: the vertices inside that the camera sees (all with `through`, X-ray), or in
/// edge and face mode the edges and faces with every corner inside; `add` keeps the selection,
/// `subtract` removes them instead.
void box_select(Selection& selection, const PointerScene& scene, const HiddenElements& hidden, glm::vec2 a, glm::vec2 b,
                bool add, bool subtract, bool through);
/// For the status bar: "3 selected, edge mode: 2 edges".
std::string selection_summary(const Selection& selection, const CovarianceMesh& mesh, SelectMode mode, bool through);

}  // namespace gps
