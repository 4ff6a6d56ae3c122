// The knife as a modal tool, and where a click lands on the control mesh.
#include "ui/tools/knife_tool.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "core/modelling/knife.h"
#include "core/support/error.h"
#include "ui/document/editor_document.h"
#include "view/snap_point.h"

namespace gps {

namespace {

constexpr float kSnapPixels = 8.0f;  // how near a corner, edge middle or edge a click snaps to it

// Whether no face hides point p: none that the ray through p's pixel meets nearer than p.
bool unhidden(const CovarianceMesh& mesh, const Viewport& view, const Vec3& p) {
  const auto at = visible_pixel(view.camera, view.width, view.height, p);
  if (!at) return false;
  const glm::vec2 pixel = glm::vec2(*at) - glm::vec2(0.5f);  // the pixel whose centre p projects to
  const Vec3 eye = to_vec(pixel_ray(view.camera, view.width, view.height, pixel).origin);
  const auto face = find_snap_point(mesh, view, pixel, SnapTarget::face, {}, 0.0f);
  return !face || (p - eye).norm() <= (face->point - eye).norm() + 1e-3 * bounding_box_diagonal(mesh);
}

}  // namespace

std::optional<Vec3> knife_point_under(const CovarianceMesh& mesh, const Viewport& view, glm::vec2 pixel) {
  if (const auto corner = find_snap_point(mesh, view, pixel, SnapTarget::vertex, {}, kSnapPixels);
      corner && unhidden(mesh, view, corner->point))
    return corner->point;
  NearestProjected nearest(view.camera, view.width, view.height, pixel, kSnapPixels, 0.5f);
  std::vector<Vec3> middles;
  for (size_t e = 0; e < mesh.n_edges(); ++e) {
    middles.push_back((mesh.mean(size_t(mesh.edge(e)[0])) + mesh.mean(size_t(mesh.edge(e)[1]))) / 2);
    nearest.consider(int(middles.size()) - 1, middles.back());
  }
  if (nearest.best() >= 0 && unhidden(mesh, view, middles[size_t(nearest.best())]))
    return middles[size_t(nearest.best())];
  if (const auto edge = find_snap_point(mesh, view, pixel, SnapTarget::edge, {}, kSnapPixels);
      edge && unhidden(mesh, view, edge->point))
    return edge->point;
  if (const auto face = find_snap_point(mesh, view, pixel, SnapTarget::face, {}, kSnapPixels)) return face->point;
  return std::nullopt;
}

KnifeTool::KnifeTool(ToolContext&) { show_count(); }

void KnifeTool::show_count() {
  error_ = false;
  status_ = "knife: " + std::to_string(points_.size()) + (points_.size() == 1 ? " point" : " points") +
            "; click on the mesh to add one (snaps to corners and edge middles), Enter or Space cuts, "
            "Backspace takes one back, Esc cancels";
}

ToolResult KnifeTool::handle(const InputEvent& e, ToolContext& ctx) {
  if (cancels(e)) {
    ctx.report("knife cancelled", false);
    return ToolResult::cancelled;
  }
  if (e.type == InputEvent::Type::press && e.button == 0) {
    const std::optional<Vec3> p = knife_point_under(ctx.document.mesh(), ctx.viewport, e.position);
    if (!p) {
      status_ = "knife: that is not on the mesh; click on a face";
      error_ = true;
    } else if (points_.empty() || (*p - points_.back()).norm() > 0) {
      points_.push_back(*p);
      show_count();
    }
    return ToolResult::consumed;
  }
  // The wheel, the middle button and the pointer's moves go on to the view (zoom, orbit, pan).
  const bool middle = (e.type == InputEvent::Type::press || e.type == InputEvent::Type::release) && e.button == 2;
  if (e.type == InputEvent::Type::scroll || e.type == InputEvent::Type::move || middle) return ToolResult::passed_on;
  if (e.type != InputEvent::Type::key_press) return ToolResult::consumed;
  if (e.key == GLFW_KEY_BACKSPACE) {
    if (!points_.empty()) points_.pop_back();
    show_count();
  } else if (e.key == GLFW_KEY_ENTER || e.key == GLFW_KEY_KP_ENTER || e.key == GLFW_KEY_SPACE) {
    if (points_.size() < 2) {
      status_ = "knife: click at least 2 points on the mesh before cutting";
      error_ = true;
      return ToolResult::consumed;
    }
    try {
      const Modelled cut = knife(ctx.document.mesh(), points_);
      ctx.install(cut, nullptr);
      ctx.note("knife: " + cut.summary, false);
    } catch (const Error& refusal) {  // nothing changed: the path stays to be mended
      status_ = std::string("knife refused: ") + refusal.what() + " (Backspace takes a point back, Esc cancels)";
      error_ = true;
      return ToolResult::consumed;
    }
    return ToolResult::confirmed;
  }
  return ToolResult::consumed;
}

// The path as a line through its points, on to the pointer.
void KnifeTool::draw_overlay(ImDrawList& draw, const ToolContext& ctx) const {
  const Viewport& v = ctx.viewport;
  std::vector<ImVec2> pixels;
  for (const Vec3& p : points_)
    if (const auto q = project_to_pixel(v.camera, v.width, v.height, p)) pixels.emplace_back(q->x, q->y);
  const ImU32 colour = IM_COL32(255, 210, 60, 255);
  if (pixels.size() >= 2) draw.AddPolyline(pixels.data(), int(pixels.size()), colour, ImDrawFlags_None, 2.0f);
  if (!pixels.empty())
    draw.AddLine(pixels.back(), ImVec2(ctx.cursor.x, ctx.cursor.y), IM_COL32(255, 210, 60, 140), 1.5f);
  for (const ImVec2& p : pixels) draw.AddCircleFilled(p, 4.0f, colour);
}

}  // namespace gps
