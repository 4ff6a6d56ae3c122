#include "ui/tools/handle_drag_tool.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "ui/document/editor_document.h"
#include "ui/editing/selection.h"
#include "view/projection.h"

namespace gps {

std::unique_ptr<ModalTool> HandleDragTool::start(ToolContext& ctx, const Handle& grabbed, double k_sigma,
                                                 glm::vec2 pixel, bool common_frame, const Vec3& pivot) {
  ctx.document.begin_edit();
  return std::unique_ptr<ModalTool>(new HandleDragTool(ctx, grabbed, k_sigma, pixel, common_frame, pivot));
}

HandleDragTool::HandleDragTool(ToolContext& ctx, const Handle& grabbed, double k_sigma, glm::vec2 pixel,
                               bool common_frame, const Vec3& pivot)
    : drag_(ctx.document.mesh(), ctx.selection.vertices(), grabbed, k_sigma, ctx.viewport, pixel, common_frame, pivot),
      followed_(ctx.cursor) {
  rebuild_reach(ctx);
  status_ = drag_.describe();
}

ToolResult HandleDragTool::handle(const InputEvent& e, ToolContext& ctx) {
  switch (e.type) {
    case InputEvent::Type::move:
      if (followed_ != ctx.cursor) update(ctx);
      return ToolResult::consumed;
    case InputEvent::Type::release:
      if (e.button != 0) return ToolResult::consumed;
      if (followed_ != ctx.cursor) update(ctx);  // the motion that came with the release
      ctx.document.commit_edit();                // one undo step per drag, soft and mirrored vertices included
      return ToolResult::confirmed;
    case InputEvent::Type::scroll:
      if (!ctx.reach.proportional) return ToolResult::passed_on;  // the wheel zooms
      ctx.reach.radius *= std::pow(1.15, double(e.steps));
      rebuild_reach(ctx);
      update(ctx);
      return ToolResult::consumed;
    case InputEvent::Type::key_press:
      if (e.key == GLFW_KEY_ESCAPE) {
        ctx.document.cancel_edit();
        ctx.report("drag cancelled", false);
        return ToolResult::cancelled;
      }
      if (e.key == GLFW_KEY_ENTER || e.key == GLFW_KEY_KP_ENTER) {
        ctx.document.commit_edit();
        return ToolResult::confirmed;
      }
      return key(e.key, ctx) ? ToolResult::consumed : ToolResult::passed_on;  // others reach the commands
    case InputEvent::Type::text: {
      const char c = char(e.codepoint);
      if (drag_.handle().is_centre() && ((c >= '0' && c <= '9') || c == '.' || c == '-' || c == 'e')) {
        drag_.set_typed(drag_.typed() + c);
        update(ctx);
      }
      return ToolResult::consumed;
    }
    case InputEvent::Type::press:
    case InputEvent::Type::key_release:
    case InputEvent::Type::drop:
      return ToolResult::consumed;
  }
  return ToolResult::consumed;
}

// Digits are typed as text: as keys they would reach the commands (1/2/3: select modes).
bool HandleDragTool::key(int key, ToolContext& ctx) {
  if ((key >= GLFW_KEY_0 && key <= GLFW_KEY_9) || (key >= GLFW_KEY_KP_0 && key <= GLFW_KEY_KP_9)) return true;
  if (!drag_.handle().is_centre()) return false;
  if (key == GLFW_KEY_X || key == GLFW_KEY_Y || key == GLFW_KEY_Z) {
    drag_.constrain(ctx.shift ? MoveConstraint::plane : MoveConstraint::axis, key - GLFW_KEY_X);
  } else if (key == GLFW_KEY_N) {
    drag_.constrain(MoveConstraint::normal);
  } else if (key == GLFW_KEY_BACKSPACE) {
    std::string typed = drag_.typed();
    if (!typed.empty()) typed.pop_back();
    drag_.set_typed(typed);
  } else {
    return false;
  }
  update(ctx);
  return true;
}

// The proportional and mirrored reach of the drag, from the positions at its start.
void HandleDragTool::rebuild_reach(ToolContext& ctx) {
  std::vector<Vec3> means(ctx.document.mesh().n_vertices());
  for (size_t v = 0; v < means.size(); ++v) means[v] = ctx.document.start_mean(int(v));
  ctx.document.revert_edit();  // vertices that leave the reach go back to their start
  reach_ = edit_reach(means, drag_.vertices(), ctx.reach, ctx.hidden_vertices);
}

void HandleDragTool::update(ToolContext& ctx) {
  followed_ = ctx.cursor;
  const auto changes = drag_.update(ctx.viewport, ctx.cursor, DragModifiers{ctx.shift, ctx.ctrl});
  if (!changes) return;
  apply_reach(ctx.document, reach_, *changes, ctx.reach.mirror_axis);
  status_ = drag_.describe() +
            (reach_.size() > drag_.vertices().size() ? "  (" + std::to_string(reach_.size()) + " vertices)" : "");
  error_ = false;
}

void HandleDragTool::draw_overlay(ImDrawList& draw, const ToolContext& ctx) const {
  if (!ctx.reach.proportional) return;
  const Viewport& v = ctx.viewport;
  const Vec3 start = drag_.start_centre();
  const double pixels = ctx.reach.radius / world_per_pixel(v.camera, v.height, start);
  if (const auto centre = visible_pixel(v.camera, v.width, v.height, start))
    draw.AddCircle(ImVec2(centre->x, centre->y), float(std::min(pixels, 1e4)), IM_COL32(255, 255, 255, 160), 64, 1.5f);
}

std::optional<ToolGizmo> HandleDragTool::gizmo(const Viewport& view) const {
  return ToolGizmo{drag_.frame(view), drag_.handle()};
}

}  // namespace gps
