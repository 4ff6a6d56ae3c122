#include "ui/edit_history.h"

#include <limits>

namespace gps {

VertexEdit EditHistory::begin(const CovarianceMesh& mesh, const std::vector<int>& vertices) {
  VertexEdit e;
  e.vertices = vertices;
  for (const int v : vertices) {
    e.means_before.push_back(mesh.mean(size_t(v)));
    e.covariances_before.push_back(mesh.covariance(size_t(v)));
  }
  return e;
}

void EditHistory::commit(VertexEdit edit, const CovarianceMesh& mesh) {
  edit.means_after.clear();
  edit.covariances_after.clear();
  for (const int v : edit.vertices) {
    edit.means_after.push_back(mesh.mean(size_t(v)));
    edit.covariances_after.push_back(mesh.covariance(size_t(v)));
  }
  if (saved_ > position_) saved_ = std::numeric_limits<size_t>::max();  // the saved state is gone
  steps_.resize(position_);
  steps_.push_back(std::move(edit));
  ++position_;
}

std::vector<int> EditHistory::undo(CovarianceMesh& mesh) {
  if (!can_undo()) return {};
  const VertexEdit& e = steps_[--position_];
  for (size_t i = 0; i < e.vertices.size(); ++i) {
    mesh.set_mean(size_t(e.vertices[i]), e.means_before[i]);
    mesh.set_covariance(size_t(e.vertices[i]), e.covariances_before[i]);
  }
  return e.vertices;
}

std::vector<int> EditHistory::redo(CovarianceMesh& mesh) {
  if (!can_redo()) return {};
  const VertexEdit& e = steps_[position_++];
  for (size_t i = 0; i < e.vertices.size(); ++i) {
    mesh.set_mean(size_t(e.vertices[i]), e.means_after[i]);
    mesh.set_covariance(size_t(e.vertices[i]), e.covariances_after[i]);
  }
  return e.vertices;
}

}  // namespace gps
