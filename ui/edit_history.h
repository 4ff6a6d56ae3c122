#pragma once
// Undo and redo for vertex edits: one step per drag, preset or numeric entry; exact restore.
#include <vector>

#include "core/mesh/covariance_mesh.h"

namespace gps {

/// The Gaussians of some vertices before and after one user action.
struct VertexEdit {
  std::vector<int> vertices;
  std::vector<Vec3> means_before, means_after;
  std::vector<Mat3> covariances_before, covariances_after;
};

class EditHistory {
public:
  /// Records the state of `vertices` before an action (call before changing them).
  static VertexEdit begin(const CovarianceMesh& mesh, const std::vector<int>& vertices);
  /// Completes `edit` with the state after the action and pushes it (drops the redo steps).
  void commit(VertexEdit edit, const CovarianceMesh& mesh);

  bool can_undo() const { return position_ > 0; }
  bool can_redo() const { return position_ < steps_.size(); }
  /// Restores the state before the last step; returns the vertices it changed.
  std::vector<int> undo(CovarianceMesh& mesh);
  std::vector<int> redo(CovarianceMesh& mesh);

  /// Unsaved changes: the history is not where it was when mark_saved() was last called.
  bool dirty() const { return position_ != saved_; }
  void mark_saved() { saved_ = position_; }
  void clear() { steps_.clear(), position_ = 0, saved_ = 0; }

private:
  std::vector<VertexEdit> steps_;
  size_t position_ = 0;  // steps_[0, position_) are applied
  size_t saved_ = 0;     // never reachable again once a branch drops it: SIZE_MAX
};

}  // namespace gps
