#pragma once
// The mesh being edited: where it came from, its undo history and unsaved-changes state.
#include <string>

#include "core/covariance_mesh.h"
#include "ui/edit_history.h"

namespace gps {

class EditorDocument {
public:
  /// Reads a mesh file (covariance PLY, or OBJ/OFF/STL/plain PLY with inferred covariances).
  /// On failure throws gps::Error (one line naming the file) and leaves the document as it was.
  void open(const std::string& path);
  /// A built-in sample, untitled (saving asks for a file name).
  void open_sample(const std::string& name);
  /// Writes the mesh (atomically) to `path`, which becomes the document's file when it is a PLY;
  /// keeps binary PLY binary. Throws gps::Error and keeps everything on failure.
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
  bool dirty() const { return history.dirty(); }
  /// Changes whenever a different mesh is loaded (the topology, plans and stencils must be rebuilt).
  unsigned generation() const { return generation_; }

  CovarianceMesh mesh;
  EditHistory history;

private:
  void replace(CovarianceMesh mesh, const std::string& source, const std::string& ply_path, const std::string& name);

  std::string source_path_, ply_path_, display_name_;
  bool binary_ = false;
  unsigned generation_ = 0;
};

}  // namespace gps
