#include "ui/selection.h"

#include <algorithm>

#include "view/projection.h"

namespace gps {

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
