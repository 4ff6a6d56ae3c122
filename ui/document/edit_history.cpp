#include "ui/document/edit_history.h"

#include <limits>
#include <utility>

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

MeshReplacement mesh_replacement(const CovarianceMesh& before, const CovarianceMesh& after,
                                 const std::vector<int>& origin) {
  MeshReplacement r;
  r.forward = mesh_delta(before, after, origin);
  r.back = mesh_delta(after, before, inverse_origin(origin, before.n_vertices()));
  return r;
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
  push({std::move(edit), std::nullopt, std::nullopt});
}

void EditHistory::commit(MeshReplacement replacement, PendingReplacement waiting) {
  if (pending()) make_deltas(steps_[position_ - 1], steps_[position_ - 1].pending->held, waiting.held);
  push({VertexEdit{}, std::move(replacement), std::move(waiting)});
}

void EditHistory::make_deltas(Step& step, const CovarianceMesh& before, const CovarianceMesh& after) {
  MeshReplacement deltas = mesh_replacement(before, after, step.pending->origin);
  step.replacement->forward = std::move(deltas.forward);
  step.replacement->back = std::move(deltas.back);
  step.pending.reset();
}

void EditHistory::settle(const CovarianceMesh& mesh) {
  if (pending()) make_deltas(steps_[position_ - 1], steps_[position_ - 1].pending->held, mesh);
  if (redo_pending()) make_deltas(steps_[position_], mesh, steps_[position_].pending->held);
}

bool EditHistory::fold_into_pending(const SelectionRecord& selection) {
  if (!pending()) return false;
  steps_[position_ - 1].replacement->selection_after = selection;
  if (saved_ == position_) saved_ = std::numeric_limits<size_t>::max();  // saved before the edit: gone
  return true;
}

bool EditHistory::fold_last_into_replacement(const CovarianceMesh& mesh, const SelectionRecord& selection) {
  if (position_ < 2 || position_ != steps_.size()) return false;
  Step& replaced = steps_[position_ - 2];
  if (!replaced.replacement || steps_[position_ - 1].replacement) return false;
  // The operation's deltas told again for `mesh`, which the edit changed from what the operation left.
  MeshReplacement& r = *replaced.replacement;
  const VertexEdit& edit = steps_[position_ - 1].edit;
  retell_gaussians(r.forward, r.back, mesh, edit.vertices, edit.means_before, edit.covariances_before);
  r.selection_after = selection;
  steps_.pop_back();
  if (saved_ == position_ - 1) saved_ = std::numeric_limits<size_t>::max();  // between the two: gone
  if (saved_ == position_) saved_ = position_ - 1;
  --position_;
  return true;
}

size_t EditHistory::bytes() const {
  size_t total = 0;
  for (const Step& s : steps_) {
    const VertexEdit& e = s.edit;
    total += e.vertices.size() * sizeof(int) + (e.means_before.size() + e.means_after.size()) * sizeof(Vec3) +
             (e.covariances_before.size() + e.covariances_after.size()) * sizeof(Mat3);
    if (s.replacement) total += s.replacement->forward.bytes() + s.replacement->back.bytes();
    if (s.pending)
      total += s.pending->held.n_vertices() * (sizeof(Vec3) + sizeof(Mat3)) +
               s.pending->held.n_corners() * sizeof(int) + s.pending->origin.size() * sizeof(int);
  }
  return total;
}

void EditHistory::drop_redo() {
  if (saved_ > position_) saved_ = std::numeric_limits<size_t>::max();  // the saved state is gone
  steps_.resize(position_);
}

Restored EditHistory::undo(CovarianceMesh& mesh) {
  if (!can_undo()) return {};
  if (pending()) {  // the meshes swap; the vertices' sources are those the back delta would give
    Step& s = steps_[--position_];
    std::swap(mesh, s.pending->held);
    return {{},
            s.replacement->selection_before,
            delta_vertex_sources(s.pending->held.n_vertices(), mesh.n_vertices(),
                                 inverse_origin(s.pending->origin, mesh.n_vertices()))};
  }
  settle(mesh);  // a redo step that waits: the undo moves past it
  const Step& s = steps_[--position_];
  if (s.replacement) {
    mesh = apply_delta(mesh, s.replacement->back);
    return {{}, s.replacement->selection_before, vertex_sources(s.replacement->back)};
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
  if (redo_pending()) {  // the meshes swap back
    Step& s = steps_[position_++];
    std::swap(mesh, s.pending->held);
    return {{},
            s.replacement->selection_after,
            delta_vertex_sources(s.pending->held.n_vertices(), mesh.n_vertices(), s.pending->origin)};
  }
  settle(mesh);
  const Step& s = steps_[position_++];
  if (s.replacement) {
    mesh = apply_delta(mesh, s.replacement->forward);
    return {{}, s.replacement->selection_after, vertex_sources(s.replacement->forward)};
  }
  const VertexEdit& e = s.edit;
  for (size_t i = 0; i < e.vertices.size(); ++i) {
    mesh.set_mean(size_t(e.vertices[i]), e.means_after[i]);
    mesh.set_covariance(size_t(e.vertices[i]), e.covariances_after[i]);
  }
  return {e.vertices, std::nullopt, {}};
}

}  // namespace gps
