// Adjust last operation (F9, as Blender's): a panel with the numbers of the last operation a tool
// made (a bevel's width, segments and profile; a spin's angle and steps; a grid fill's span and
// offset; an extrusion's or duplication's move; an inset's thickness and depth; a loop cut's number
// of cuts and slide). A number changed and entered makes the operation again from the mesh before it
// and puts the result in place of the old one, as the same single undo step; a refused value leaves
// the result as it was.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "core/support/error.h"
#include "ui/editor/editor_app.h"

namespace gps {

namespace {
// Where the panel sits: below the statistics, clear of the Inspector and View panels on the right.
constexpr float kAdjustPanelX = 10.0f, kAdjustPanelY = 230.0f;
}  // namespace

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
  if (!show_adjust_last_) return;
  const bool current = adjustable_ && adjustable_->step == document_.last_step() && !document_.editing() && !tool_;
  ImGui::SetNextWindowPos(ImVec2(kAdjustPanelX, kAdjustPanelY), ImGuiCond_Always);
  if (!ImGui::Begin("Adjust last operation", &show_adjust_last_,
                    ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::End();
    return;
  }
  if (!current) {
    ImGui::TextDisabled("no operation to adjust: extrude, duplicate, inset, loop cut, bevel, spin or grid fill first");
    ImGui::End();
    return;
  }
  std::vector<double> values;
  for (const AdjustableParameter& p : adjustable_->parameters) values.push_back(p.value);
  bool entered = false;
  const ImGuiInputTextFlags flags = ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll;
  for (size_t k = 0; k < values.size(); ++k) {
    const AdjustableParameter& p = adjustable_->parameters[k];
    ImGui::SetNextItemWidth(120.0f);
    if (p.integer) {
      int n = int(values[k]);
      if (ImGui::InputInt(p.label.c_str(), &n, 1, 10, flags)) values[k] = double(n), entered = true;
    } else {
      if (ImGui::InputDouble(p.label.c_str(), &values[k], 0.0, 0.0, "%.4g", flags)) entered = true;
    }
    values[k] = std::clamp(values[k], p.min, p.max);
  }
  ImGui::TextDisabled("%s: Enter applies", adjustable_->name.c_str());
  ImGui::End();
  if (entered) adjust_last(values);
}

}  // namespace gps
