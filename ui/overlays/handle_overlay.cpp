#include "ui/overlays/handle_overlay.h"

#include <imgui.h>

namespace gps {

void draw_handle_overlay(ImDrawList& draw, const Viewport& v, const std::optional<HandleFrame>& gizmo,
                         const std::optional<Handle>& hovered) {
  const auto pixel = [&v](const Vec3& p) -> std::optional<ImVec2> {
    const auto q = visible_pixel(v.camera, v.width, v.height, p);
    if (!q) return std::nullopt;
    return ImVec2(q->x, q->y);
  };
  if (!gizmo) return;
  const ImU32 axis_colours[3] = {IM_COL32(235, 80, 80, 255), IM_COL32(90, 210, 90, 255), IM_COL32(90, 150, 255, 255)};
  const ImU32 highlight = IM_COL32(255, 240, 90, 255), outline = IM_COL32(0, 0, 0, 200);
  const auto dot = [&](ImVec2 at, bool lit, ImU32 colour) {
    draw.AddCircleFilled(at, lit ? 7.0f : 5.0f, lit ? highlight : colour);
    draw.AddCircle(at, lit ? 7.0f : 5.0f, outline);
  };
  const auto centre = pixel(gizmo->centre);
  if (!centre) return;
  for (int axis = 0; axis < 3; ++axis)
    for (const int side : {1, -1}) {
      const auto end = pixel(gizmo->end(axis, side));
      if (!end) continue;
      draw.AddLine(*centre, *end, axis_colours[axis], 2.0f);
      dot(*end, hovered && hovered->axis == axis && hovered->side == side, axis_colours[axis]);
    }
  dot(*centre, hovered && hovered->is_centre(), IM_COL32(245, 245, 245, 255));
}

}  // namespace gps
