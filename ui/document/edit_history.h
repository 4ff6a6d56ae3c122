#pragma once
// Undo and redo: one step per drag, preset, numeric entry or modelling operation; exact restore.
// A vertex edit keeps the Gaussians of the vertices it changed; a modelling operation, which may
// change the topology, keeps the mesh after it told as a change of the mesh before and the other way
// round (core/mesh/mesh_delta.h), in memory proportional to what it changed, and the selections that
// go with them.
#include <cstdint>
#include <optional>
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "core/mesh/mesh_delta.h"
#include "ui/document/selection_record.h"

namespace gps {

/// The Gaussians of some vertices before and after one user action.
struct VertexEdit {
  std::vector<int> vertices;
  std::vector<Vec3> means_before, means_after;
  std::vector<Mat3> covariances_before, covariances_after;
};

/// A modelling operation: the mesh after it as a change of the mesh before (`forward`) and the mesh
/// before as a change of the mesh after (`back`), with the selection of each.
struct MeshReplacement {
  MeshDelta forward, back;
  SelectionRecord selection_before, selection_after;
};

/// A modelling operation whose deltas are made later (EditHistory::settle): its other mesh, held whole,
/// and its vertices' origins (per vertex of the mesh after it, its index in the mesh before). While the
/// step is applied `held` is the mesh before it (the owner holds the mesh after); once it is undone,
/// the mesh after it.
struct PendingReplacement {
  CovarianceMesh held;
  std::vector<int> origin;
};

/// The replacement of `before` by `after`; `origin`: per vertex of `after`, its index in `before` (−1
/// new; empty: the indices kept).
MeshReplacement mesh_replacement(const CovarianceMesh& before, const CovarianceMesh& after,
                                 const std::vector<int>& origin);

/// What an undo or redo restored: the vertices whose Gaussians it set, or a whole mesh (with the
/// selection that goes with it).
struct Restored {
  std::vector<int> vertices;
  std::optional<SelectionRecord> replaced_selection;  // set: the mesh was replaced as a whole
  std::vector<int> origin;  // then: per vertex, its index in the mesh replaced (−1 new); empty: kept
};

class EditHistory {
public:
  /// Records the state of `vertices` before an action (call before changing them).
  static VertexEdit begin(const CovarianceMesh& mesh, const std::vector<int>& vertices);
  /// Completes `edit` with the state after the action and pushes it (drops the redo steps).
  void commit(VertexEdit edit, const CovarianceMesh& mesh);
  /// Pushes a replacement of the whole mesh (drops the redo steps) whose deltas wait (`replacement`
  /// holds its selections): made by settle(), when an undo moves past it, or when the next operation is
  /// pushed, from `waiting.held` and the mesh after the operation, which is the owner's mesh while the
  /// step is the last (the owner settles before it changes that mesh otherwise). A waiting step before
  /// it is settled first, `waiting.held` being its mesh after.
  void commit(MeshReplacement replacement, PendingReplacement waiting);
  /// Whether the last applied step is a replacement whose deltas wait.
  bool pending() const { return position_ > 0 && steps_[position_ - 1].pending.has_value(); }
  /// Makes the waiting deltas of the last applied step, or of the step a redo applies next, from the
  /// mesh the step holds and `mesh` (the owner's, with no edit open).
  void settle(const CovarianceMesh& mesh);
  /// An edit folded into the last step while its deltas wait: the mesh after it, which the deltas
  /// will take, now has the edit; `selection` goes with it. False when the last step is not pending.
  bool fold_into_pending(const SelectionRecord& selection);
  /// Folds the last step, a vertex edit, into the replacement before it: the replacement's result
  /// becomes `mesh` (e.g. an extrusion and the move that follows it undo as one). False when the last
  /// two steps are not a replacement then a vertex edit.
  bool fold_last_into_replacement(const CovarianceMesh& mesh, const SelectionRecord& selection);

  /// Forgets the steps that redo would replay (a cancelled tool's undone step).
  void drop_redo();

  bool can_undo() const { return position_ > 0; }
  bool can_redo() const { return position_ < steps_.size(); }
  /// Restores the state before the last step. A step whose deltas wait swaps its meshes instead (the
  /// mesh after it is held for a redo, which swaps them back); a waiting step that the undo moves
  /// past is settled first.
  Restored undo(CovarianceMesh& mesh);
  Restored redo(CovarianceMesh& mesh);

  /// The memory the steps hold, in bytes: their deltas and vertex edits, and a waiting step's mesh
  /// (its Gaussians and corners).
  size_t bytes() const;

  /// Unsaved changes: the history is not where it was when mark_saved() was last called.
  bool dirty() const { return position_ != saved_; }
  void mark_saved() { saved_ = position_; }
  /// Unsaved with no step to undo: a mesh that differs from its file as opened (a repaired one).
  void mark_unsaved() { saved_ = SIZE_MAX; }
  void clear() { steps_.clear(), position_ = 0, saved_ = 0; }
  /// A number naming the last applied step, never given to another step of this history (0: none
  /// applied): an adjustment of the last operation checks that it is still the last step.
  std::uint64_t last_step() const { return position_ > 0 ? steps_[position_ - 1].serial : 0; }

private:
  struct Step {
    VertexEdit edit;
    std::optional<MeshReplacement> replacement;  // set: the step replaced the whole mesh
    std::optional<PendingReplacement> pending;   // set: its deltas wait (the step at the position only)
    std::uint64_t serial = 0;
  };
  void push(Step step);
  bool redo_pending() const { return position_ < steps_.size() && steps_[position_].pending.has_value(); }
  static void make_deltas(Step& step, const CovarianceMesh& before, const CovarianceMesh& after);
  std::vector<Step> steps_;
  size_t position_ = 0;  // steps_[0, position_) are applied
  size_t saved_ = 0;     // never reachable again once a branch drops it: SIZE_MAX
  std::uint64_t serials_ = 0;
};

}  // namespace gps
