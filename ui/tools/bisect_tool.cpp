// Bisect as a modal tool.
#include "ui/tools/bisect_tool.h"

#include <imgui.h>

#include <Eigen/Geometry>

#include "core/modelling/bisect.h"

namespace gps {

namespace {
constexpr float kShortestLine = 4.0f;  // pixels: a shorter drag is a click, not a line
}  // namespace

BisectTool::BisectTool(ToolContext&) {
  status_ = "bisect: drag a line across the mesh (the cut is the plane seen along it); Esc cancels";
}

std::optional<BisectTool::Plane> BisectTool::plane_through(const Viewport& view, glm::vec2 a, glm::vec2 b) {
  if (glm::length(b - a) < kShortestLine) return std::nullopt;
  const Ray ra = pixel_ray(view.camera, view.width, view.height, a);
  const Ray rb = pixel_ray(view.camera, view.width, view.height, b);
  const Vec3 oa = to_vec(ra.origin), da = to_vec(ra.direction);
  // The far point of b's ray at the target's depth: with a's ray, it spans the plane (perspective
  // rays share the eye; parallel ones differ by their origins).
  const double depth = (to_vec(view.camera.target) - to_vec(view.camera.eye_double())).norm();
  const Vec3 pb = to_vec(rb.origin) + depth * to_vec(rb.direction);
  const Vec3 normal = da.cross(pb - oa);
  if (!(normal.norm() > 0)) return std::nullopt;
  return Plane{oa, normal.normalized()};
}

ToolResult BisectTool::handle(const InputEvent& e, ToolContext& ctx) {
  if (cancels(e)) {
    ctx.report("bisect cancelled", false);
    return ToolResult::cancelled;
  }
  if (e.type == InputEvent::Type::press && e.button == 0) {
    from_ = to_ = e.position;
    return ToolResult::consumed;
  }
  if (e.type == InputEvent::Type::move) {
    to_ = e.position;
    return ToolResult::consumed;
  }
  if (e.type == InputEvent::Type::release && e.button == 0 && from_) {
    const auto plane = plane_through(ctx.viewport, *from_, e.position);
    from_.reset();
    if (!plane) {
      status_ = "bisect: drag a longer line across the mesh; Esc cancels";
      return ToolResult::consumed;
    }
    const Plane p = *plane;
    if (!ctx.operate(
            "bisect", [&](const CovarianceMesh& mesh) { return bisect(mesh, p.point, p.normal); }, nullptr)) {
      status_ = "bisect: that line cuts no face; drag another, or Esc";
      error_ = true;
      return ToolResult::consumed;
    }
    return ToolResult::confirmed;
  }
  if (e.type == InputEvent::Type::scroll) return ToolResult::passed_on;  // the wheel zooms
  return ToolResult::consumed;
}

void BisectTool::draw_overlay(ImDrawList& draw, const ToolContext&) const {
  if (!from_) return;
  draw.AddLine(ImVec2(from_->x, from_->y), ImVec2(to_.x, to_.y), IM_COL32(255, 255, 255, 255), 2.0f);
}

}  // namespace gps
