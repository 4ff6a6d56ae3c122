#include "ui/editing/selection.h"

#include <algorithm>
#include <iterator>

#include "view/projection.h"

namespace gps {

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

void Selection::click(int vertex, bool toggle) {
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
  std::vector<int> removed = outside;
  std::sort(removed.begin(), removed.end());
  std::vector<int> kept;
  std::set_difference(vertices_.begin(), vertices_.end(), removed.begin(), removed.end(), std::back_inserter(kept));
  vertices_ = std::move(kept);
}

void Selection::invert(size_t n_vertices) {
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
  vertices_.resize(n_vertices);
  for (size_t i = 0; i < n_vertices; ++i) vertices_[i] = int(i);
}

void Selection::clear() {
  vertices_.clear();
  last_clicked_ = -1;
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
