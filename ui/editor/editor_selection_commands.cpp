// Selecting in Blender's three modes: a click picks a vertex, an edge or a face; Alt+click a loop,
// Ctrl+Alt+click a ring, Ctrl+click a path; boxes take only what the camera sees unless selecting
// through. The Select menu's commands are in editor_select_menu.cpp.

#include <algorithm>
#include <array>

#include "core/modelling/loop_cut.h"
#include "core/modelling/mesh_queries.h"
#include "core/modelling/operation_words.h"
#include "core/support/error.h"
#include "ui/editor/editor_app.h"
#include "view/element_picking.h"
#include "view/picking.h"
#include "view/visible_vertices.h"

namespace gps {

namespace {

constexpr float kClickRadius = 8.0f;  // window pixels from a vertex or an edge
constexpr float kLoopRadius = 24.0f;  // an Alt+click takes the nearest edge this near

std::vector<int> corners(const CovarianceMesh& mesh, int face) {
  const std::span<const int> face_corners = mesh.face(size_t(face));
  return {face_corners.begin(), face_corners.end()};
}

}  // namespace

void EditorApp::set_select_mode(SelectMode mode) {
  select_mode_ = mode;
  selection_.hold_for(mode, document_.mesh());
  set_status(select_mode_name(mode) + " select mode", false);
}

std::vector<int> EditorApp::vertices_under(glm::vec2 pixel) const {
  const Viewport v = viewport();
  const CovarianceMesh& mesh = document_.mesh();
  if (select_mode_ == SelectMode::vertex) {
    if (const int vertex = pick_vertex(v.camera, v.width, v.height, pixel, mesh, kClickRadius, &hidden_.vertex_mask());
        vertex >= 0)
      return {vertex};
  } else if (select_mode_ == SelectMode::edge) {
    if (const auto edge = pick_edge(v, pixel, mesh, kClickRadius, &hidden_.edge_mask()))
      return {(*edge)[0], (*edge)[1]};
  }
  const int face = pick_face(v, pixel, mesh, &hidden_.face_mask());
  return face >= 0 ? corners(mesh, face) : std::vector<int>{};
}

void EditorApp::click_select(glm::vec2 pixel, bool toggle) {
  if (select_mode_ == SelectMode::vertex) {
    selection_.click(pick(pixel), toggle);
    return;
  }
  const Viewport v = viewport();
  const CovarianceMesh& mesh = document_.mesh();
  std::vector<int> group;
  const auto edge =
      select_mode_ == SelectMode::edge ? pick_edge(v, pixel, mesh, kClickRadius, &hidden_.edge_mask()) : std::nullopt;
  const int face = select_mode_ == SelectMode::face ? pick_face(v, pixel, mesh, &hidden_.face_mask()) : -1;
  if (edge)
    group = {(*edge)[0], (*edge)[1]};
  else if (face >= 0)
    group = corners(mesh, face);
  // The active vertex: the group's vertex nearest the cursor.
  int active = group.empty() ? -1 : group.front();
  float nearest = 1e30f;
  for (const int vertex : group)
    if (const auto p = visible_pixel(v.camera, v.width, v.height, mesh.mean(size_t(vertex))))
      if (const float d = glm::length(glm::vec2(*p) - pixel); d < nearest) nearest = d, active = vertex;
  if (select_mode_ == SelectMode::edge)
    selection_.click_edges(mesh, edge ? std::vector<EdgeEnds>{*edge} : std::vector<EdgeEnds>{}, active, toggle);
  else
    selection_.click_faces(mesh, face >= 0 ? std::vector<int>{face} : std::vector<int>{}, active, toggle);
}

void EditorApp::loop_select(glm::vec2 pixel, bool toggle) {
  const Viewport v = viewport();
  const CovarianceMesh& mesh = document_.mesh();
  const auto edge = pick_edge(v, pixel, mesh, kLoopRadius, &hidden_.edge_mask());
  if (!edge) return;
  const auto [a, b] = *edge;
  try {
    if (select_mode_ == SelectMode::edge) {
      const std::vector<EdgeEnds> loop = edge_loop_edges(mesh, a, b);
      selection_.click_edges(mesh, loop, a, toggle);
      set_status("edge loop: " + count_of(loop.size(), "edge", "edges"), false);
      return;
    }
    if (select_mode_ == SelectMode::face) {
      const std::vector<int> loop = face_loop(mesh, a, b);
      selection_.click_faces(mesh, loop, a, toggle);
      set_status("face loop: " + count_of(loop.size(), "face", "faces"), false);
      return;
    }
    const std::vector<int> loop = edge_loop(mesh, a, b);
    selection_.click_group(loop, a, toggle);
    set_status("edge loop: " + std::to_string(loop.size()) + " vertices", false);
  } catch (const Error& e) {
    set_status(std::string("loop select: ") + e.what(), true);
  }
}

// The ring a loop cut through the edge under the pointer would cross (core's edge_ring): its edges in
// edge mode, their ends in vertex mode; in face mode the faces between them, as Blender's ring of
// edges selects a loop of faces there.
void EditorApp::ring_select(glm::vec2 pixel, bool toggle) {
  const CovarianceMesh& mesh = document_.mesh();
  const auto edge = pick_edge(viewport(), pixel, mesh, kLoopRadius, &hidden_.edge_mask());
  if (!edge) return;
  const auto [a, b] = *edge;
  try {
    if (select_mode_ == SelectMode::face) {
      const std::vector<int> loop = face_loop(mesh, a, b);
      selection_.click_faces(mesh, loop, a, toggle);
      set_status("face loop: " + count_of(loop.size(), "face", "faces"), false);
      return;
    }
    std::vector<EdgeEnds> ring;
    for (const auto& [x, y] : edge_ring(mesh, a, b).edges) ring.push_back({std::min(x, y), std::max(x, y)});
    if (select_mode_ == SelectMode::edge) {
      selection_.click_edges(mesh, ring, a, toggle);
    } else {
      std::vector<int> ends;
      for (const auto& [x, y] : ring) ends.insert(ends.end(), {x, y});
      std::sort(ends.begin(), ends.end());
      ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
      selection_.click_group(ends, a, toggle);
    }
    set_status("edge ring: " + count_of(ring.size(), "edge", "edges"), false);
  } catch (const Error& e) {
    set_status(std::string("ring select: ") + e.what(), true);
  }
}

// Adds the shortest path along the edges (core's shortest_path) from the active vertex to the vertex
// under the pointer, which becomes the active one; in edge mode the path's edges; in face mode the
// faces from the active face to the face under the pointer. With nothing to start from it is a plain click.
void EditorApp::path_select(glm::vec2 pixel) {
  if (select_mode_ == SelectMode::face) return face_path_select(pixel);
  const int from = selection_.active(), to = pick(pixel);
  if (from < 0 || to < 0) return click_select(pixel, false);
  const CovarianceMesh& mesh = document_.mesh();
  try {
    const std::vector<int> path = shortest_path(mesh, from, to);
    if (select_mode_ == SelectMode::edge) {
      std::vector<EdgeEnds> edges;
      for (size_t k = 0; k + 1 < path.size(); ++k)
        edges.push_back({std::min(path[k], path[k + 1]), std::max(path[k], path[k + 1])});
      selection_.hold_edges(mesh);
      selection_.select_edges(mesh, edges, true);
    } else {
      selection_.select(path, true);
    }
    selection_.set_active(to);
    set_status("shortest path: " + count_of(path.size() - 1, "edge", "edges"), false);
  } catch (const Error& e) {
    set_status(std::string("shortest path: ") + e.what(), true);
  }
}

void EditorApp::face_path_select(glm::vec2 pixel) {
  const CovarianceMesh& mesh = document_.mesh();
  const int from = selection_.active_face(mesh), to = pick_face(viewport(), pixel, mesh, &hidden_.face_mask());
  if (from < 0 || to < 0) return click_select(pixel, false);
  try {
    const std::vector<int> path = shortest_face_path(mesh, from, to, &hidden_.face_mask());
    selection_.select_faces(mesh, path, true);
    selection_.set_active_face(mesh, to);
    set_status("shortest path: " + count_of(path.size(), "face", "faces"), false);
  } catch (const Error& e) {
    set_status(std::string("shortest path: ") + e.what(), true);
  }
}

void EditorApp::box_select(glm::vec2 a, glm::vec2 b, bool add, bool subtract) {
  const Viewport v = viewport();
  const CovarianceMesh& mesh = document_.mesh();
  std::vector<int> inside = hidden_.elements().shown(vertices_in_box(v.camera, v.width, v.height, a, b, mesh));
  if (!select_through_ && !inside.empty()) {
    const std::vector<char> visible = visible_vertices(v, mesh);
    std::vector<int> seen;
    for (const int vertex : inside)
      if (visible[size_t(vertex)]) seen.push_back(vertex);
    inside = std::move(seen);
  }
  if (select_mode_ == SelectMode::edge) {  // the edges with both ends inside
    const std::vector<EdgeEnds> edges = edges_within(mesh, inside);
    if (subtract)
      selection_.deselect_edges(mesh, edges);
    else
      selection_.select_edges(mesh, edges, add);
    return;
  }
  if (select_mode_ == SelectMode::face) {  // the faces with all corners inside
    const std::vector<int> faces = faces_within(mesh, inside);
    if (subtract)
      selection_.deselect_faces(mesh, faces);
    else
      selection_.select_faces(mesh, faces, add);
    return;
  }
  if (subtract)
    selection_.deselect(inside);
  else
    selection_.select(inside, add);
}

std::string EditorApp::selection_summary() const {
  std::string text = std::to_string(selection_.vertices().size()) + " selected";
  const CovarianceMesh& mesh = document_.mesh();
  if (select_mode_ == SelectMode::edge) {
    text += ", edge mode: " + count_of(selection_.empty() ? 0 : selection_.edges(mesh).size(), "edge", "edges");
  } else if (select_mode_ == SelectMode::face) {
    const size_t n = selection_.empty() ? 0 : selection_.faces(mesh).size();
    text += ", face mode: " + std::to_string(n) + (n == 1 ? " face" : " faces");
  } else {
    text += ", vertex mode";
  }
  return text + (select_through_ ? ", X-ray" : "");
}

}  // namespace gps
