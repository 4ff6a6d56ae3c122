#pragma once
// A drag of the gizmo's handles as a modal tool: a left press on an axis end scales or rotates the
// selected Gaussians, on the centre moves them (ui/editing/axis_handles.h), with the proportional
// and mirrored reach of the edit (ui/editing/edit_reach.h), as one undo step. Releasing the button
// or Enter keeps the edit, Esc restores it. During a move X / Y / Z (Shift: the plane normal to it)
// and N constrain it and digits type its distance; with proportional editing the wheel sets the radius.
#include <memory>
#include <optional>
#include <vector>

#include "ui/editing/axis_handles.h"
#include "ui/tools/modal_tool.h"

namespace gps {

class HandleDragTool : public ModalTool {
public:
  /// Begins the document's edit of the selection by `grabbed`, pressed at `pixel` on the gizmo whose
  /// centre is `pivot` (axis ends at `k_sigma` σ; `common_frame`: every vertex takes the grabbed one's axes).
  static std::unique_ptr<ModalTool> start(ToolContext& ctx, const Handle& grabbed, double k_sigma, glm::vec2 pixel,
                                          bool common_frame, const Vec3& pivot);

  ToolResult handle(const InputEvent& event, ToolContext& ctx) override;
  /// The proportional radius, as a circle around where the grabbed vertex was.
  void draw_overlay(ImDrawList& draw, const ToolContext& ctx) const override;
  std::optional<ToolGizmo> gizmo(const Viewport& view) const override;
  size_t reached() const override { return reach_.size(); }

private:
  HandleDragTool(ToolContext& ctx, const Handle& grabbed, double k_sigma, glm::vec2 pixel, bool common_frame,
                 const Vec3& pivot);
  bool key(int key, ToolContext& ctx);  // whether the key was the drag's
  void rebuild_reach(ToolContext& ctx);
  void update(ToolContext& ctx);

  HandleDrag drag_;
  std::vector<ReachedVertex> reach_;   // the vertices the drag changes, and how strongly
  std::optional<glm::vec2> followed_;  // the cursor the edit last followed
};

}  // namespace gps
