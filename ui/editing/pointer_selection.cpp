#include "ui/editing/pointer_selection.h"

#include <algorithm>
#include <array>

#include "core/modelling/loop_cut.h"
#include "core/modelling/mesh_queries.h"
#include "core/modelling/operation_words.h"
#include "core/support/error.h"
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

// In face mode both an Alt+click and a Ctrl+Alt+click take the loop of faces across the edge a-b.
SelectionNote click_face_loop(Selection& selection, const CovarianceMesh& mesh, int a, int b, bool toggle) {
  const std::vector<int> loop = face_loop(mesh, a, b);
  selection.click_faces(mesh, loop, a, toggle);
  return {"face loop: " + count_of(loop.size(), "face", "faces")};
}

SelectionNote face_path_select(Selection& selection, const PointerScene& scene, glm::vec2 pixel) {
  const CovarianceMesh& mesh = scene.mesh;
  const int from = selection.active_face(mesh), to = pick_face(scene.view, pixel, mesh, &scene.hidden_faces);
  if (from < 0 || to < 0) {
    click_select(selection, scene, pixel, -1, false);
    return {};
  }
  try {
    const std::vector<int> path = shortest_face_path(mesh, from, to, &scene.hidden_faces);
    selection.select_faces(mesh, path, true);
    selection.set_active_face(mesh, to);
    return {"shortest path: " + count_of(path.size(), "face", "faces")};
  } catch (const Error& e) {
    return {std::string("shortest path: ") + e.what(), true};
  }
}

// Whether the camera sees edge {a, b} where it passes nearest `pixel`: the front-most face there is
// one of the edge's own (or, within a few pixels of an end, one of that end's), or no face is (its
// silhouette).
bool edge_seen_near(const PointerScene& scene, const std::array<int, 2>& edge, glm::vec2 pixel) {
  const Viewport& v = scene.view;
  const CovarianceMesh& mesh = scene.mesh;
  const auto a = visible_pixel(v.camera, v.width, v.height, mesh.mean(size_t(edge[0])));
  const auto b = visible_pixel(v.camera, v.width, v.height, mesh.mean(size_t(edge[1])));
  if (!a || !b) return true;  // crossing the near plane: nothing is in front of it
  const glm::vec2 from(*a), along = glm::vec2(*b) - from;
  const float t = glm::dot(along, along) > 0.0f
                      ? std::clamp(glm::dot(pixel - from, along) / glm::dot(along, along), 0.0f, 1.0f)
                      : 0.0f;
  const int front = pick_face(v, from + t * along, mesh, &scene.hidden_faces);
  if (front < 0) return true;
  const std::span<const int> corners = mesh.face(size_t(front));
  const auto has = [&](int x) { return std::find(corners.begin(), corners.end(), x) != corners.end(); };
  constexpr float kAtAnEnd = 3.0f;  // pixels: there the faces of the end vertex meet the edge
  return (has(edge[0]) && has(edge[1])) || (has(edge[0]) && t * glm::length(along) <= kAtAnEnd) ||
         (has(edge[1]) && (1.0f - t) * glm::length(along) <= kAtAnEnd);
}

// The edge nearest `pixel` within `radius` that is not hidden and, without X-ray, that the camera
// sees there (Blender's solid mode); the next nearest where a face covers the nearest.
std::optional<std::array<int, 2>> edge_under(const PointerScene& scene, glm::vec2 pixel, float radius) {
  constexpr int kCoveredTries = 16;
  std::vector<char> unpickable = scene.hidden_edges;
  unpickable.resize(scene.mesh.n_edges(), 0);
  for (int k = 0; k < kCoveredTries; ++k) {
    const auto edge = pick_edge(scene.view, pixel, scene.mesh, radius, &unpickable);
    if (!edge || scene.through || edge_seen_near(scene, *edge, pixel)) return edge;
    unpickable[size_t(scene.mesh.find_edge((*edge)[0], (*edge)[1]))] = 1;
  }
  return std::nullopt;
}

}  // namespace

std::vector<char> unpickable_vertices(const PointerScene& scene) {
  std::vector<char> out = scene.hidden_vertices;
  out.resize(scene.mesh.n_vertices(), 0);
  if (scene.through) return out;
  const std::vector<char> visible = visible_vertices(scene.view, scene.mesh);
  for (size_t v = 0; v < out.size(); ++v) out[v] = out[v] || !visible[v];
  return out;
}

int pick_visible_vertex(const PointerScene& scene, glm::vec2 pixel, float radius) {
  const Viewport& v = scene.view;
  const std::vector<char> unpickable = unpickable_vertices(scene);
  return pick_vertex(v.camera, v.width, v.height, pixel, scene.mesh, radius, &unpickable);
}

std::vector<int> vertices_under(const PointerScene& scene, glm::vec2 pixel) {
  const Viewport& v = scene.view;
  const CovarianceMesh& mesh = scene.mesh;
  if (scene.mode == SelectMode::vertex) {
    if (const int vertex = pick_visible_vertex(scene, pixel, kClickRadius); vertex >= 0) return {vertex};
  } else if (scene.mode == SelectMode::edge) {
    if (const auto edge = edge_under(scene, pixel, kClickRadius)) return {(*edge)[0], (*edge)[1]};
  }
  const int face = pick_face(v, pixel, mesh, &scene.hidden_faces);
  return face >= 0 ? corners(mesh, face) : std::vector<int>{};
}

void click_select(Selection& selection, const PointerScene& scene, glm::vec2 pixel, int vertex, bool toggle) {
  if (scene.mode == SelectMode::vertex) {
    selection.click(vertex, toggle);
    return;
  }
  const Viewport& v = scene.view;
  const CovarianceMesh& mesh = scene.mesh;
  std::vector<int> group;
  const auto edge = scene.mode == SelectMode::edge ? edge_under(scene, pixel, kClickRadius) : std::nullopt;
  const int face = scene.mode == SelectMode::face ? pick_face(v, pixel, mesh, &scene.hidden_faces) : -1;
  if (edge)
    group = {(*edge)[0], (*edge)[1]};
  else if (face >= 0)
    group = corners(mesh, face);
  // The active vertex: the group's vertex nearest the cursor.
  int active = group.empty() ? -1 : group.front();
  float nearest = 1e30f;
  for (const int g : group)
    if (const auto p = visible_pixel(v.camera, v.width, v.height, mesh.mean(size_t(g))))
      if (const float d = glm::length(glm::vec2(*p) - pixel); d < nearest) nearest = d, active = g;
  if (scene.mode == SelectMode::edge)
    selection.click_edges(mesh, edge ? std::vector<EdgeEnds>{*edge} : std::vector<EdgeEnds>{}, active, toggle);
  else
    selection.click_faces(mesh, face >= 0 ? std::vector<int>{face} : std::vector<int>{}, active, toggle);
}

SelectionNote loop_select(Selection& selection, const PointerScene& scene, glm::vec2 pixel, bool toggle) {
  const CovarianceMesh& mesh = scene.mesh;
  const auto edge = edge_under(scene, pixel, kLoopRadius);
  if (!edge) return {};
  const auto [a, b] = *edge;
  try {
    if (scene.mode == SelectMode::edge) {
      const std::vector<EdgeEnds> loop = edge_loop_edges(mesh, a, b);
      selection.click_edges(mesh, loop, a, toggle);
      return {"edge loop: " + count_of(loop.size(), "edge", "edges")};
    }
    if (scene.mode == SelectMode::face) return click_face_loop(selection, mesh, a, b, toggle);
    const std::vector<int> loop = edge_loop(mesh, a, b);
    selection.click_group(loop, a, toggle);
    return {"edge loop: " + std::to_string(loop.size()) + " vertices"};
  } catch (const Error& e) {
    return {std::string("loop select: ") + e.what(), true};
  }
}

SelectionNote ring_select(Selection& selection, const PointerScene& scene, glm::vec2 pixel, bool toggle) {
  const CovarianceMesh& mesh = scene.mesh;
  const auto edge = edge_under(scene, pixel, kLoopRadius);
  if (!edge) return {};
  const auto [a, b] = *edge;
  try {
    if (scene.mode == SelectMode::face) return click_face_loop(selection, mesh, a, b, toggle);
    std::vector<EdgeEnds> ring;
    for (const auto& [x, y] : edge_ring(mesh, a, b).edges) ring.push_back({std::min(x, y), std::max(x, y)});
    if (scene.mode == SelectMode::edge) {
      selection.click_edges(mesh, ring, a, toggle);
    } else {
      std::vector<int> ends;
      for (const auto& [x, y] : ring) ends.insert(ends.end(), {x, y});
      std::sort(ends.begin(), ends.end());
      ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
      selection.click_group(ends, a, toggle);
    }
    return {"edge ring: " + count_of(ring.size(), "edge", "edges")};
  } catch (const Error& e) {
    return {std::string("ring select: ") + e.what(), true};
  }
}

SelectionNote path_select(Selection& selection, const PointerScene& scene, glm::vec2 pixel, int vertex) {
  if (scene.mode == SelectMode::face) return face_path_select(selection, scene, pixel);
  const int from = selection.active();
  if (from < 0 || vertex < 0) {
    click_select(selection, scene, pixel, vertex, false);
    return {};
  }
  const CovarianceMesh& mesh = scene.mesh;
  try {
    const std::vector<int> path = shortest_path(mesh, from, vertex);
    if (scene.mode == SelectMode::edge) {
      std::vector<EdgeEnds> edges;
      for (size_t k = 0; k + 1 < path.size(); ++k)
        edges.push_back({std::min(path[k], path[k + 1]), std::max(path[k], path[k + 1])});
      selection.hold_edges(mesh);
      selection.select_edges(mesh, edges, true);
    } else {
      selection.select(path, true);
    }
    selection.set_active(vertex);
    return {"shortest path: " + count_of(path.size() - 1, "edge", "edges")};
  } catch (const Error& e) {
    return {std::string("shortest path: ") + e.what(), true};
  }
}

void box_select(Selection& selection, const PointerScene& scene, const HiddenElements& hidden, glm::vec2 a, glm::vec2 b,
                bool add, bool subtract, bool through) {
  const Viewport& v = scene.view;
  const CovarianceMesh& mesh = scene.mesh;
  std::vector<int> inside = hidden.shown(vertices_in_box(v.camera, v.width, v.height, a, b, mesh));
  if (!through && !inside.empty()) {
    const std::vector<char> visible = visible_vertices(v, mesh);
    std::vector<int> seen;
    for (const int vertex : inside)
      if (visible[size_t(vertex)]) seen.push_back(vertex);
    inside = std::move(seen);
  }
  if (scene.mode == SelectMode::edge) {  // the edges with both ends inside
    const std::vector<EdgeEnds> edges = edges_within(mesh, inside);
    if (subtract)
      selection.deselect_edges(mesh, edges);
    else
      selection.select_edges(mesh, edges, add);
    return;
  }
  if (scene.mode == SelectMode::face) {  // the faces with all corners inside
    const std::vector<int> faces = faces_within(mesh, inside);
    if (subtract)
      selection.deselect_faces(mesh, faces);
    else
      selection.select_faces(mesh, faces, add);
    return;
  }
  if (subtract)
    selection.deselect(inside);
  else
    selection.select(inside, add);
}

std::string selection_summary(const Selection& selection, const CovarianceMesh& mesh, SelectMode mode, bool through) {
  std::string text = std::to_string(selection.vertices().size()) + " selected";
  if (mode == SelectMode::edge) {
    text += ", edge mode: " + count_of(selection.empty() ? 0 : selection.edges(mesh).size(), "edge", "edges");
  } else if (mode == SelectMode::face) {
    const size_t n = selection.empty() ? 0 : selection.faces(mesh).size();
    text += ", face mode: " + std::to_string(n) + (n == 1 ? " face" : " faces");
  } else {
    text += ", vertex mode";
  }
  return text + (through ? ", X-ray" : "");
}

}  // namespace gps
