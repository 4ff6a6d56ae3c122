#pragma once
// gpsurf-editor: a Dear ImGui editor of covariance meshes on the GPU pipeline.
#include <string>

#include "core/io/mesh_io.h"

namespace gps {

struct EditorOptions {
  std::string file;        // the mesh to open; "" = the embedded default sample
  std::string play;        // events file to replay (then the editor finishes and exits)
  std::string record;      // write the live input to this events file on exit
  std::string screenshot;  // scripted: PNG of the window after the events
  std::string save;        // scripted: save the mesh here after the events
  std::string stats;       // on exit, write frame and edit-to-frame figures here (JSON)
  int width = 1280, height = 800;
  bool vsync = true;
  int scheme = -1;      // ViewOptions::scheme from the command line; −1: as kept in the settings
  bool warren = false;  // Loop with Warren's β
  int up_axis = -1;     // the world axis drawn upward for `file` (0 x, 1 y, 2 z); −1: as kept for it
  ImportOptions import;  // how `file` is read: repaired (--repair), the weld tolerance of every repair (--weld)
};

/// Opens the window and runs the editor until the user quits (or, with play/screenshot/save, until
/// the script is done). Returns the exit code; errors that stop it are gps::Error (one line). A `file`
/// that does not open leaves the default sample open under its error (and the repair dialog where the
/// repair mends it), but for a run that must write a screenshot or a save of it, which stops there.
int run_editor(const EditorOptions& options);

}  // namespace gps
