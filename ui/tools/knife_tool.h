#pragma once
// The knife (K) as a modal tool, as Blender's: each left click adds a point where the pointer meets
// the control mesh (snapped to a corner or an edge's middle within a few pixels, else onto an edge
// near it), the path drawn over the view with a line on to the pointer; Enter or Space cuts along it
// (core/modelling/knife.h) as one undo step, Backspace takes back the last point, Esc or a right click
// cancels.
#include <optional>
#include <vector>

#include "ui/tools/modal_tool.h"

namespace gps {

/// Where a click at `pixel` lands on the control mesh (view/snap_point.h's points): the corner, else
/// the edge's middle, else the point of an edge projected nearest within a few pixels and hidden by
/// no face, else where the pixel's ray first meets a face; nullopt off the mesh.
std::optional<Vec3> knife_point_under(const CovarianceMesh& mesh, const Viewport& view, glm::vec2 pixel);

class KnifeTool : public ModalTool {
public:
  explicit KnifeTool(ToolContext& ctx);

  ToolResult handle(const InputEvent& event, ToolContext& ctx) override;
  void draw_overlay(ImDrawList& draw, const ToolContext& ctx) const override;

private:
  void show_count();

  std::vector<Vec3> points_;
};

}  // namespace gps
