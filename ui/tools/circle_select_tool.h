#pragma once
// Circle select (C), as Blender's: a circle follows the pointer; dragging with the left button adds
// what it passes over to the selection (the vertices it covers; in edge mode the edges with both ends
// covered; in face mode the faces whose centre it covers), with Shift or the middle button it takes
// them away; the wheel sets its radius. Only what the camera sees is taken, unless selecting through
// (X-ray). Enter, Esc or a right click ends it; the selection stays as painted.
#include <optional>
#include <vector>

#include "ui/editing/selection.h"
#include "ui/tools/modal_tool.h"

namespace gps {

class CircleSelectTool : public ModalTool {
public:
  CircleSelectTool(ToolContext& ctx, SelectMode mode, bool through);

  ToolResult handle(const InputEvent& event, ToolContext& ctx) override;
  void draw_overlay(ImDrawList& draw, const ToolContext& ctx) const override;

  static constexpr float kDefaultRadius = 25.0f;  // window pixels, Blender's

private:
  void paint(glm::vec2 at, bool add, ToolContext& ctx);
  void describe();

  SelectMode mode_;
  float radius_ = kDefaultRadius;
  std::optional<bool> painting_;  // while a button is down: adding (true) or taking away
  std::vector<char> visible_;     // per vertex, as the view was when the tool started
  glm::vec2 at_{0.0f};
};

}  // namespace gps
