#include "ui/document/edit_history.h"

#include <limits>

#include "core/modelling/mesh_arrays.h"

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

void EditHistory::push(Step step) {
  if (saved_ > position_) saved_ = std::numeric_limits<size_t>::max();  // the saved state is gone
  steps_.resize(position_);
  step.serial = ++serials_;
  steps_.push_back(std::move(step));
  ++position_;
}

void EditHistory::commit(VertexEdit edit, const CovarianceMesh& mesh) {
  edit.means_after.clear();
  edit.covariances_after.clear();
  for (const int v : edit.vertices) {
    edit.means_after.push_back(mesh.mean(size_t(v)));
    edit.covariances_after.push_back(mesh.covariance(size_t(v)));
  }
  push({std::move(edit), std::nullopt});
}

void EditHistory::commit(MeshReplacement replacement) { push({VertexEdit{}, std::move(replacement)}); }

bool EditHistory::fold_last_into_replacement(const CovarianceMesh& mesh, const SelectionRecord& selection) {
  if (position_ < 2 || position_ != steps_.size()) return false;
  Step& replaced = steps_[position_ - 2];
  if (!replaced.replacement || steps_[position_ - 1].replacement) return false;
  replaced.replacement->after = std::make_shared<const CovarianceMesh>(mesh);
  replaced.replacement->selection_after = selection;
  steps_.pop_back();
  if (saved_ == position_ - 1) saved_ = std::numeric_limits<size_t>::max();  // between the two: gone
  if (saved_ == position_) saved_ = position_ - 1;
  --position_;
  return true;
}

void EditHistory::drop_redo() {
  if (saved_ > position_) saved_ = std::numeric_limits<size_t>::max();  // the saved state is gone
  steps_.resize(position_);
}

Restored EditHistory::undo(CovarianceMesh& mesh) {
  if (!can_undo()) return {};
  const Step& s = steps_[--position_];
  if (s.replacement) {
    mesh = *s.replacement->before;
    return {{}, s.replacement->selection_before, inverse_origin(s.replacement->origin, mesh.n_vertices())};
  }
  const VertexEdit& e = s.edit;
  for (size_t i = 0; i < e.vertices.size(); ++i) {
    mesh.set_mean(size_t(e.vertices[i]), e.means_before[i]);
    mesh.set_covariance(size_t(e.vertices[i]), e.covariances_before[i]);
  }
  return {e.vertices, std::nullopt, {}};
}

Restored EditHistory::redo(CovarianceMesh& mesh) {
  if (!can_redo()) return {};
  const Step& s = steps_[position_++];
  if (s.replacement) {
    mesh = *s.replacement->after;
    return {{}, s.replacement->selection_after, s.replacement->origin};
  }
  const VertexEdit& e = s.edit;
  for (size_t i = 0; i < e.vertices.size(); ++i) {
    mesh.set_mean(size_t(e.vertices[i]), e.means_after[i]);
    mesh.set_covariance(size_t(e.vertices[i]), e.covariances_after[i]);
  }
  return {e.vertices, std::nullopt, {}};
}

}  // namespace gps
