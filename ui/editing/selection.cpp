#include "ui/editing/selection.h"

#include <algorithm>
#include <iterator>

#include "core/modelling/mesh_queries.h"
#include "view/projection.h"

namespace gps {

namespace {

// The edges as (min, max), ascending, each once.
std::vector<EdgeEnds> normalized(std::vector<EdgeEnds> edges) {
  for (auto& e : edges)
    if (e[0] > e[1]) std::swap(e[0], e[1]);
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

}  // namespace

std::string select_mode_name(SelectMode mode) {
  switch (mode) {
    case SelectMode::vertex:
      return "vertex";
    case SelectMode::edge:
      return "edge";
    case SelectMode::face:
      return "face";
  }
  return "";
}

bool Selection::contains(int vertex) const { return std::binary_search(vertices_.begin(), vertices_.end(), vertex); }

int Selection::active() const {
  if (vertices_.empty()) return -1;
  return contains(last_clicked_) ? last_clicked_ : vertices_.front();
}

std::vector<EdgeEnds> Selection::edges(const CovarianceMesh& mesh) const {
  if (!holds_edges_) return edges_within(mesh, vertices_);
  std::vector<EdgeEnds> out;
  for (const auto& [a, b] : edges_)
    if (b < int(mesh.n_vertices()) && mesh.find_edge(a, b) >= 0) out.push_back({a, b});
  return out;
}

void Selection::click(int vertex, bool toggle) {
  release();
  if (vertex < 0) {
    if (!toggle) clear();
    return;
  }
  if (!toggle) {
    vertices_ = {vertex};
  } else if (contains(vertex)) {
    vertices_.erase(std::lower_bound(vertices_.begin(), vertices_.end(), vertex));
  } else {
    vertices_.insert(std::lower_bound(vertices_.begin(), vertices_.end(), vertex), vertex);
  }
  last_clicked_ = vertex;
}

void Selection::select(const std::vector<int>& inside, bool additive) {
  release();
  if (!additive) vertices_.clear();
  vertices_.insert(vertices_.end(), inside.begin(), inside.end());
  std::sort(vertices_.begin(), vertices_.end());
  vertices_.erase(std::unique(vertices_.begin(), vertices_.end()), vertices_.end());
}

void Selection::click_group(const std::vector<int>& group, int active, bool toggle) {
  if (group.empty()) {
    if (!toggle) clear();
    return;
  }
  const bool all_selected = std::all_of(group.begin(), group.end(), [this](int v) { return contains(v); });
  if (toggle && all_selected) {
    deselect(group);
  } else {
    select(group, toggle);
  }
  last_clicked_ = active;
}

void Selection::deselect(const std::vector<int>& outside) {
  release();
  std::vector<int> removed = outside;
  std::sort(removed.begin(), removed.end());
  std::vector<int> kept;
  std::set_difference(vertices_.begin(), vertices_.end(), removed.begin(), removed.end(), std::back_inserter(kept));
  vertices_ = std::move(kept);
}

void Selection::invert(size_t n_vertices) {
  release();
  std::vector<int> inverted;
  size_t k = 0;
  for (size_t i = 0; i < n_vertices; ++i) {
    while (k < vertices_.size() && vertices_[k] < int(i)) ++k;
    if (k < vertices_.size() && vertices_[k] == int(i)) continue;
    inverted.push_back(int(i));
  }
  vertices_ = std::move(inverted);
}

void Selection::select_all(size_t n_vertices) {
  release();
  vertices_.resize(n_vertices);
  for (size_t i = 0; i < n_vertices; ++i) vertices_[i] = int(i);
}

void Selection::clear() {
  release();
  vertices_.clear();
  last_clicked_ = -1;
}

void Selection::restore(const SelectionRecord& record) {
  select(record.vertices, false);
  if (record.holds_edges) set_edges(record.edges);
  if (record.holds_faces) set_faces(record.faces);
}

void Selection::set_edges(std::vector<EdgeEnds> edges) {
  release_faces();
  edges_ = normalized(std::move(edges));
  holds_edges_ = true;
  vertices_.clear();
  for (const auto& [a, b] : edges_) vertices_.insert(vertices_.end(), {a, b});
  std::sort(vertices_.begin(), vertices_.end());
  vertices_.erase(std::unique(vertices_.begin(), vertices_.end()), vertices_.end());
}

void Selection::hold_edges(const CovarianceMesh& mesh) {
  if (!holds_edges_) set_edges(edges_within(mesh, vertices_));
}

void Selection::click_edges(const CovarianceMesh& mesh, const std::vector<EdgeEnds>& group, int active, bool toggle) {
  if (group.empty()) {
    if (!toggle) clear();
    return;
  }
  hold_edges(mesh);
  const std::vector<EdgeEnds> picked = normalized(group);
  if (toggle && std::includes(edges_.begin(), edges_.end(), picked.begin(), picked.end()))
    deselect_edges(mesh, picked);
  else
    select_edges(mesh, picked, toggle);
  last_clicked_ = active;
}

void Selection::select_edges(const CovarianceMesh& mesh, const std::vector<EdgeEnds>& inside, bool additive) {
  hold_edges(mesh);
  std::vector<EdgeEnds> edges = additive ? edges_ : std::vector<EdgeEnds>{};
  edges.insert(edges.end(), inside.begin(), inside.end());
  set_edges(std::move(edges));
}

void Selection::deselect_edges(const CovarianceMesh& mesh, const std::vector<EdgeEnds>& outside) {
  hold_edges(mesh);
  const std::vector<EdgeEnds> removed = normalized(outside);
  std::vector<EdgeEnds> kept;
  std::set_difference(edges_.begin(), edges_.end(), removed.begin(), removed.end(), std::back_inserter(kept));
  set_edges(std::move(kept));
}

void Selection::invert_edges(const CovarianceMesh& mesh) {
  hold_edges(mesh);
  std::vector<EdgeEnds> all;
  for (size_t e = 0; e < mesh.n_edges(); ++e) all.push_back(mesh.edge(e));
  all = normalized(std::move(all));
  std::vector<EdgeEnds> inverted;
  std::set_difference(all.begin(), all.end(), edges_.begin(), edges_.end(), std::back_inserter(inverted));
  set_edges(std::move(inverted));
}

std::vector<int> Selection::faces(const CovarianceMesh& mesh) const {
  if (!holds_faces_) return faces_within(mesh, vertices_);
  std::vector<int> out;
  for (const FaceCorners& held : faces_)
    if (const int f = face_with_corners(mesh, held); f >= 0) out.push_back(f);
  if (!std::is_sorted(out.begin(), out.end())) std::sort(out.begin(), out.end());
  return out;
}

int Selection::face_with_corners(const CovarianceMesh& mesh, const FaceCorners& held) {
  if (held.empty() || held.front() < 0 || held.back() >= int(mesh.n_vertices())) return -1;
  const MeshConnectivity& c = mesh.connectivity();
  // The face around its lowest corner with as many corners, each held (a face's corners are distinct,
  // so these are the held ones).
  for (int k = c.vertex_face_offsets[size_t(held.front())]; k < c.vertex_face_offsets[size_t(held.front()) + 1]; ++k) {
    const int f = c.vertex_faces[size_t(k)];
    const std::span<const int> corners = mesh.face(size_t(f));
    if (corners.size() != held.size()) continue;
    if (std::all_of(corners.begin(), corners.end(),
                    [&](int v) { return std::binary_search(held.begin(), held.end(), v); }))
      return f;
  }
  return -1;
}

int Selection::active_face(const CovarianceMesh& mesh) const {
  if (!holds_faces_ || !std::binary_search(faces_.begin(), faces_.end(), active_face_)) return -1;
  return face_with_corners(mesh, active_face_);
}

void Selection::set_active_face(const CovarianceMesh& mesh, int face) {
  const std::vector<FaceCorners> corners = corner_sets(mesh, {face});
  if (holds_faces_ && !corners.empty() && std::binary_search(faces_.begin(), faces_.end(), corners.front()))
    active_face_ = corners.front();
}

std::vector<FaceCorners> Selection::corner_sets(const CovarianceMesh& mesh, const std::vector<int>& faces) {
  std::vector<FaceCorners> out;
  for (const int f : faces) {
    if (f < 0 || f >= int(mesh.n_faces())) continue;
    FaceCorners corners(mesh.face(size_t(f)).begin(), mesh.face(size_t(f)).end());
    std::sort(corners.begin(), corners.end());
    out.push_back(std::move(corners));
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

void Selection::set_faces(std::vector<FaceCorners> faces) {
  release_edges();
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  faces_ = std::move(faces);
  holds_faces_ = true;
  vertices_.clear();
  for (const FaceCorners& corners : faces_) vertices_.insert(vertices_.end(), corners.begin(), corners.end());
  std::sort(vertices_.begin(), vertices_.end());
  vertices_.erase(std::unique(vertices_.begin(), vertices_.end()), vertices_.end());
}

void Selection::hold_for(SelectMode mode, const CovarianceMesh& mesh) {
  if (mode == SelectMode::edge)
    hold_edges(mesh);
  else if (mode == SelectMode::face)
    hold_faces(mesh);
  else
    release();
}

void Selection::hold_faces(const CovarianceMesh& mesh) {
  if (!holds_faces_) set_faces(corner_sets(mesh, faces_within(mesh, vertices_)));
}

void Selection::click_faces(const CovarianceMesh& mesh, const std::vector<int>& faces, int active, bool toggle) {
  if (faces.empty()) {
    if (!toggle) clear();
    return;
  }
  hold_faces(mesh);
  const std::vector<FaceCorners> picked = corner_sets(mesh, faces);
  if (toggle && std::includes(faces_.begin(), faces_.end(), picked.begin(), picked.end()))
    deselect_faces(mesh, faces);
  else
    select_faces(mesh, faces, toggle);
  last_clicked_ = active;
  if (faces.size() == 1) set_active_face(mesh, faces.front());
}

void Selection::select_faces(const CovarianceMesh& mesh, const std::vector<int>& faces, bool additive) {
  hold_faces(mesh);
  std::vector<FaceCorners> held = additive ? faces_ : std::vector<FaceCorners>{};
  for (FaceCorners& corners : corner_sets(mesh, faces)) held.push_back(std::move(corners));
  set_faces(std::move(held));
}

void Selection::deselect_faces(const CovarianceMesh& mesh, const std::vector<int>& faces) {
  hold_faces(mesh);
  const std::vector<FaceCorners> removed = corner_sets(mesh, faces);
  std::vector<FaceCorners> kept;
  std::set_difference(faces_.begin(), faces_.end(), removed.begin(), removed.end(), std::back_inserter(kept));
  set_faces(std::move(kept));
}

void Selection::invert_faces(const CovarianceMesh& mesh) {
  hold_faces(mesh);
  std::vector<int> all(mesh.n_faces());
  for (size_t f = 0; f < all.size(); ++f) all[f] = int(f);
  std::vector<FaceCorners> inverted;
  const std::vector<FaceCorners> every = corner_sets(mesh, all);
  std::set_difference(every.begin(), every.end(), faces_.begin(), faces_.end(), std::back_inserter(inverted));
  set_faces(std::move(inverted));
}

std::vector<int> vertices_in_box(const Camera& camera, int width, int height, glm::vec2 a, glm::vec2 b,
                                 const CovarianceMesh& mesh) {
  const glm::vec2 lo = glm::min(a, b), hi = glm::max(a, b) + glm::vec2(1.0f);  // pixel squares, inclusive
  std::vector<int> inside;
  for (size_t i = 0; i < mesh.n_vertices(); ++i) {
    const auto p = visible_pixel(camera, width, height, mesh.mean(i));
    if (!p) continue;
    if (p->x >= lo.x && p->x <= hi.x && p->y >= lo.y && p->y <= hi.y) inside.push_back(int(i));
  }
  return inside;
}

}  // namespace gps
