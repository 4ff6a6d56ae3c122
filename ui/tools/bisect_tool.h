#pragma once
// Bisect as a modal tool, as Blender's: a line dragged across the view (left button down, move, up)
// cuts the mesh by the plane that holds the line and the view direction (core/modelling/bisect.h),
// as one undo step when the button is let go. The line is drawn while dragging; Esc or a right click
// leaves the mesh as it was.
#include <memory>
#include <optional>

#include "ui/tools/modal_tool.h"

namespace gps {

class BisectTool : public ModalTool {
public:
  explicit BisectTool(ToolContext& ctx);

  ToolResult handle(const InputEvent& event, ToolContext& ctx) override;
  void draw_overlay(ImDrawList& draw, const ToolContext& ctx) const override;

  /// The plane seen edge-on along the line from pixel `a` to pixel `b`: through both pixels' rays
  /// (for a perspective view, through the eye). nullopt where the line is too short to define it.
  struct Plane {
    Vec3 point, normal;
  };
  static std::optional<Plane> plane_through(const Viewport& view, glm::vec2 a, glm::vec2 b);

private:
  std::optional<glm::vec2> from_;  // where the line started (the button is down)
  glm::vec2 to_{0.0f};
};

}  // namespace gps
