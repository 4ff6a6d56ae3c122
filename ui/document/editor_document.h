#pragma once
// The mesh being edited: where it came from, and every change to its Gaussians as one transaction
// (begin, set, commit) that records the undo step, the unsaved-changes state and the vertices the
// GPU must update, in one place.
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/io/mesh_io.h"
#include "core/mesh/covariance_mesh.h"
#include "core/modelling/mesh_arrays.h"
#include "ui/document/edit_history.h"

namespace gps {

/// A plane x, y or z = 0 that edits keep vertices on (the mirror modifier's clipping): a vertex that
/// starts an edit within `tolerance` of it keeps its coordinate along `axis` at 0.
struct PlaneClip {
  int axis = 0;
  double tolerance = 0.0;
};

class EditorDocument {
public:
  /// Reads a mesh file (covariance PLY, or OBJ/OFF/STL/plain PLY with inferred covariances).
  /// On failure throws gps::Error (one line naming the file) and leaves the document as it was.
  /// Read with `options` (core/io/mesh_io.h); with options.repair the mesh is read repaired
  /// (core/io/mesh_repair.h), what the repair did goes to `report` where given, and the document is
  /// unsaved: the mesh is not its file's. `notes` gets what the reader read leniently.
  void open(const std::string& path, const ImportOptions& options = {}, RepairReport* report = nullptr,
            std::vector<std::string>* notes = nullptr);
  /// A built-in sample, untitled (saving asks for a file name).
  void open_sample(const std::string& name);
  /// Writes the mesh (atomically) to `path`, which becomes the document's file when it is a PLY;
  /// binary little endian, unless the document was opened from an ASCII PLY (which stays text).
  /// Throws gps::Error and keeps everything on failure.
  void save(const std::string& path);

  /// Whether Save can write back where the mesh came from (a covariance PLY of ours to keep); false
  /// for samples and imported OBJ/OFF/STL (Save then asks for a .ply name).
  bool can_save_in_place() const { return !ply_path_.empty(); }
  /// The file Save writes (empty when can_save_in_place() is false).
  const std::string& ply_path() const { return ply_path_; }
  /// The file or sample the mesh came from, for titles and the recent list ("" for a sample).
  const std::string& source_path() const { return source_path_; }
  /// A short name for the title bar: the file name, or "sample NAME".
  const std::string& display_name() const { return display_name_; }
  bool dirty() const { return history_.dirty(); }
  const CovarianceMesh& mesh() const { return mesh_; }

  // Edits. Between begin_edit() and commit_edit() (or cancel_edit()) set_mean/set_covariance
  // change vertices; the first change of a vertex records its start value.
  void begin_edit();
  bool editing() const { return edit_.has_value(); }
  void set_mean(int vertex, const Vec3& mean);  // on the clip plane, where the vertex started there
  void set_covariance(int vertex, const Mat3& covariance);
  /// Sets every vertex whose Gaussian differs in `mesh` (a mesh of the same vertices: a tool's result
  /// recomputed from the mesh before it) to that Gaussian. False, changing nothing, where the vertex
  /// counts differ.
  bool set_gaussians(const CovarianceMesh& mesh);
  /// The value a vertex had when the open edit began (its current value outside an edit).
  Vec3 start_mean(int vertex) const;
  const Mat3& start_covariance(int vertex) const;
  /// Puts every vertex changed by the open edit back to its start value (the edit stays open).
  void revert_edit();
  /// Closes the edit: one undo step when it changed anything. Returns whether it did.
  bool commit_edit();
  /// Closes the edit, restoring the start values; no undo step.
  void cancel_edit();

  /// Replaces the mesh by a modelling operation's result as one undo step, which restores the mesh
  /// exactly (vertices, faces, their order and values) and `selection_before` with it; the redo
  /// selects the result's vertices. Closes an open edit first. The GPU must rebuild for the new mesh
  /// (take_changed() does not list it). The result's mesh is taken over, not copied, where it is given
  /// to keep. The step's deltas (core/mesh/mesh_delta.h) are made later, not in the operation's time:
  /// by settle_history() or the next step; until then the mesh before is kept whole, and an undo
  /// (an adjustment of the operation too) swaps the meshes back without them.
  void apply(Modelled result, const SelectionRecord& selection_before);
  /// Makes the undo step of the last operation, or of the one undone last, where it waits (apply,
  /// undo), outside an open edit: what an editor does in a frame without input.
  void settle_history();
  /// Closes the open edit and folds it into the modelling step just applied, so that both undo as
  /// one (an extrusion and its move); `selection` goes with the result. Without such a step it
  /// commits the edit as its own step. Returns whether anything changed.
  bool commit_edit_into_last_operation(const SelectionRecord& selection);

  /// Undoes the last step and forgets it (no redo): a modal tool cancelled after its operation was
  /// applied. Returns the selection before it when it replaced the mesh.
  std::optional<SelectionRecord> discard_last_operation();

  /// The memory the undo history holds (EditHistory::bytes).
  size_t history_bytes() const { return history_.bytes(); }
  /// Names the last applied step (EditHistory::last_step).
  std::uint64_t last_step() const { return history_.last_step(); }
  bool can_undo() const { return !editing() && history_.can_undo(); }
  bool can_redo() const { return !editing() && history_.can_redo(); }
  /// Undo and redo; when the step replaced the whole mesh they return the selection that goes with
  /// the restored mesh (the GPU must rebuild), else nullopt (take_changed() lists the vertices).
  std::optional<SelectionRecord> undo();
  std::optional<SelectionRecord> redo();
  /// After an undo or redo that replaced the mesh: each vertex's index in the mesh it replaced (−1
  /// new; empty: indices kept), for plans that follow the change (core/plans/surface_replanner.h).
  const std::vector<int>& replaced_origin() const { return replaced_origin_; }

  /// Keeps the vertices on the plane that start an edit on it (none: no clipping).
  void set_clip(std::optional<PlaneClip> clip) { clip_ = clip; }

  /// The vertices whose Gaussians changed since the last call (ascending, unique): what the GPU
  /// must re-read. A new mesh is not listed: whoever opens it rebuilds from scratch.
  std::vector<int> take_changed();

private:
  void replace(CovarianceMesh mesh, const std::string& source, const std::string& ply_path, const std::string& name);
  /// Whether `edit` changed any of its vertices in the mesh.
  bool edit_changed(const VertexEdit& edit) const;
  /// Settles the history's waiting step with the mesh as it was before `edit` (applied to it, not
  /// committed): the operation's mesh after.
  void settle_under(const VertexEdit& edit);
  void touch(int vertex);

  CovarianceMesh mesh_;
  EditHistory history_;
  std::optional<VertexEdit> edit_;
  std::unordered_map<int, size_t> edit_index_;  // vertex → its slot in edit_
  std::vector<int> changed_;
  std::vector<int> replaced_origin_;
  std::optional<PlaneClip> clip_;
  std::string source_path_, ply_path_, display_name_;
  bool binary_ = true;
};

}  // namespace gps
