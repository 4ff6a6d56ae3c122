#pragma once
// The dialog shown when a mesh opened or dropped on the editor would be refused as read (its topology
// is one that core/io/mesh_repair.h mends): what is wrong with it, class by class with counts and
// first examples, and Repair (the repaired mesh, unsaved) or Cancel (the current mesh stays).
#include <string>
#include <vector>

namespace gps {

/// What the diagnosis of a mesh file finds: the classes that refuse it and those the repair also
/// mends, one line each (RepairReport::problems). `refused` is empty where the file is not refused for
/// its topology (it reads, or it fails for another reason) and where the repair could not make it
/// open (a part no flipping orients, as a Möbius strip): Repair is offered only for what it mends.
struct RepairFindings {
  std::vector<std::string> refused, others;
};
RepairFindings repair_findings(const std::string& path);

class RepairPrompt {
public:
  enum class Answer { none, repair, cancel };
  /// Asks about the mesh file at `path` (findings.refused not empty).
  void open(const std::string& path, RepairFindings findings);
  bool is_open() const { return open_; }
  const std::string& path() const { return path_; }
  /// Draws the dialog (Enter repairs, Esc cancels); the user's answer, once.
  Answer draw();

private:
  std::string path_;
  RepairFindings findings_;
  bool open_ = false, popup_requested_ = false;
};

}  // namespace gps
