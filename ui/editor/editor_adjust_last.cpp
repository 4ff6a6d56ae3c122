// Adjust last operation (F9, as Blender's; the panel is ui/panels/adjust_last_panel.h): a number
// changed and entered makes the last operation again from the mesh before it and puts the result in
// place of the old one, as the same single undo step; a refused value leaves the result as it was.
#include "core/support/error.h"
#include "ui/editor/editor_app.h"
#include "ui/panels/adjust_last_panel.h"

namespace gps {

void EditorApp::adjust_last(const std::vector<double>& values) {
  AdjustableOperation& op = *adjustable_;
  Modelled remade;
  try {
    remade = op.make(*op.before, values);
  } catch (const Error& e) {
    set_status(op.name + " not adjusted: " + e.what(), true);
    return;
  }
  // The mesh before it (whose copy `before` is) and its selection, which the new step restores on undo.
  if (const auto selection = document_.discard_last_operation()) selection_.restore(*selection);
  if (!operate(
          op.name, [&](const CovarianceMesh&) { return remade; }, nullptr))
    return;
  for (size_t k = 0; k < values.size(); ++k) op.parameters[k].value = values[k];
  op.step = document_.last_step();
}

void EditorApp::draw_adjust_last_panel() {
  const bool current = adjustable_ && adjustable_->step == document_.last_step() && !document_.editing() && !tool_;
  if (const auto values = gps::draw_adjust_last_panel(show_adjust_last_, current ? &*adjustable_ : nullptr))
    adjust_last(*values);
}

}  // namespace gps
