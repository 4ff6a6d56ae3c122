#pragma once
// The loop cut (Ctrl+R) as a modal tool: the edge ring under the cursor previewed with its cuts (the
// wheel or a typed number sets how many), a click cuts (core/modelling/loop_cut.h), then the new loops
// slide with the mouse, or by a typed factor, until a click or Enter; the cut and its slide are one
// undo step, Esc keeps the cut in the middle. Once ended, F9 adjusts the number of cuts and the slide.
#include <array>
#include <memory>
#include <optional>
#include <string>

#include "core/modelling/loop_cut.h"
#include "ui/tools/modal_tool.h"
#include "ui/tools/typed_number.h"
#include "ui/input/wheel_notches.h"

namespace gps {

/// The edge (its two vertices) under the cursor on a face turned toward the camera, within a pick
/// distance in pixels; nullopt for none.
std::optional<std::array<int, 2>> edge_under(const CovarianceMesh& mesh, const Viewport& view, glm::vec2 cursor);

class LoopCutTool : public ModalTool {
public:
  explicit LoopCutTool(ToolContext& ctx);

  ToolResult handle(const InputEvent& event, ToolContext& ctx) override;
  void draw_overlay(ImDrawList& draw, const ToolContext& ctx) const override;

private:
  void hover(glm::vec2 cursor, const ToolContext& ctx);
  ToolResult cut(ToolContext& ctx);
  void slide(glm::vec2 cursor, ToolContext& ctx);
  void slide_to(double slide, ToolContext& ctx);
  void typed(ToolContext& ctx);  // what is typed: the cuts before the click, the slide after
  void end(bool keep, ToolContext& ctx);

  EdgeRing ring_;  // under the cursor (empty: none)
  int cuts_ = 1;
  double slide_ = 0.0;  // the slide shown
  bool sliding_ = false;
  std::shared_ptr<const CovarianceMesh> base_;  // the mesh before the cut
  std::string summary_;                         // the cut's
  WheelNotches wheel_;
  TypedNumber typed_;
  glm::vec2 start_cursor_{0.0f};
};

}  // namespace gps
