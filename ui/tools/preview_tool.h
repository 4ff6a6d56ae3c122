#pragma once
// A modal tool whose operation is shown before it is confirmed (bevel, spin): made anew from the mesh
// before for each value and shown in place of the document's, or refused with the mesh before shown;
// confirmed as one undo step, cancelled without one.
#include <functional>
#include <optional>
#include <string>

#include "ui/tools/modal_tool.h"

namespace gps {

class PreviewTool : public ModalTool {
protected:
  /// Shows make()'s result in place of the document's mesh, or the document's where `none` (a value
  /// that does nothing); the status is `amount` + `keys`, or `amount` and why make() refused (an error).
  void preview(ToolContext& ctx, bool none, const std::function<Modelled()>& make, const std::string& amount,
               const std::string& keys);
  /// Esc or a right click, or a confirmation with nothing shown: the document's mesh shown again and
  /// "NAME cancelled" or "NAME: nothing done (WHY)" reported (`nothing`: why, where no refusal says).
  /// Returns whether the event was one of those (the tool is then cancelled).
  bool cancelled_by(const InputEvent& event, ToolContext& ctx, const std::string& name, const std::string& nothing);
  /// The result shown installed as one undo step named `name`; false where it was refused (the
  /// document's mesh shown again).
  bool install_shown(ToolContext& ctx, const std::string& name);

  std::optional<Modelled> result_;  // what is shown (nullopt: the mesh before)
  std::string refusal_;             // why the values shown cannot be made
};

}  // namespace gps
