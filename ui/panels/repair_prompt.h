#pragma once
// The dialog shown when a mesh opened or dropped on the editor does not open as read but would once
// repaired (core/io/mesh_repair.h), or opens but holds what the repair mends (coincident vertices that
// tear it apart, zero-area faces): what is wrong with it, class by class with counts and first
// examples, and Repair (the repaired mesh, unsaved) or Cancel (the current mesh stays: the one before,
// or the one just opened as read).
#include <string>
#include <vector>

#include "core/io/mesh_io.h"

namespace gps {

/// What the repair would mend in a mesh file that did not open: the classes that refuse it and the
/// others it mends, one line each (RepairReport::problems), elements numbered as the file numbers them.
/// Both are empty where the repair changes nothing or does not make the file open (a part no flipping
/// orients, as a Möbius strip, or a reason no repair touches): Repair is offered only for what it mends.
/// `options` are the editor's import options (--weld), the repair asked of them.
struct RepairFindings {
  std::vector<std::string> refused, others;
  bool offered() const { return !refused.empty() || !others.empty(); }
};
RepairFindings repair_findings(const std::string& path, const ImportOptions& options = {});

class RepairPrompt {
public:
  enum class Answer { none, repair, cancel };
  /// Asks about the mesh file at `path` (findings offered), which did not open for `refusal` (shown
  /// where no class found refuses it, as a mesh whose Gaussians a zero-area face spoils), or which
  /// `opened` as read (refusal empty).
  void open(const std::string& path, RepairFindings findings, const std::string& refusal, bool opened = false);
  bool is_open() const { return open_; }
  /// Whether the mesh asked about opened as read (Cancel keeps it).
  bool opened() const { return opened_; }
  const std::string& path() const { return path_; }
  /// Draws the dialog (Enter repairs, Esc cancels); the user's answer, once.
  Answer draw();

private:
  std::string path_;
  RepairFindings findings_;
  std::string refusal_;
  bool open_ = false, popup_requested_ = false, opened_ = false;
};

}  // namespace gps
