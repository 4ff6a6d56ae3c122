#include "ui/overlays/cursor_overlay.h"

#include <imgui.h>

#include <cmath>

namespace gps {

void draw_cursor_overlay(ImDrawList& draw, const Viewport& view, const Vec3& point) {
  const auto at = project_to_pixel(view.camera, view.width, view.height, point);
  if (!at) return;
  const ImVec2 c(at->x, at->y);
  constexpr float kRadius = 10.0f;
  constexpr int kDashes = 8;
  // The ring in alternating red and white arcs, and a black cross through a gap around the centre.
  for (int k = 0; k < kDashes; ++k) {
    const float a0 = float(2.0 * M_PI * k / kDashes), a1 = float(2.0 * M_PI * (k + 1) / kDashes);
    draw.PathArcTo(c, kRadius, a0, a1, 6);
    draw.PathStroke(k % 2 ? IM_COL32(255, 255, 255, 255) : IM_COL32(230, 40, 40, 255), 0, 2.0f);
  }
  for (const ImVec2 d : {ImVec2(1, 0), ImVec2(0, 1)}) {
    for (const float side : {-1.0f, 1.0f}) {
      const ImVec2 from(c.x + side * d.x * 4.0f, c.y + side * d.y * 4.0f);
      const ImVec2 to(c.x + side * d.x * (kRadius + 6.0f), c.y + side * d.y * (kRadius + 6.0f));
      draw.AddLine(from, to, IM_COL32(20, 20, 20, 255), 1.5f);
    }
  }
}

}  // namespace gps
