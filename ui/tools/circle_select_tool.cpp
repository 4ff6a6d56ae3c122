// Circle select as a modal tool.
#include "ui/tools/circle_select_tool.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/modelling/mesh_queries.h"
#include "ui/document/editor_document.h"
#include "view/visible_vertices.h"

namespace gps {

CircleSelectTool::CircleSelectTool(ToolContext& ctx, SelectMode mode, bool through)
    : mode_(mode),
      visible_(through ? std::vector<char>(ctx.document.mesh().n_vertices(), 1)
                       : visible_vertices(ctx.viewport, ctx.document.mesh())),
      at_(ctx.cursor) {
  describe();
}

void CircleSelectTool::describe() {
  char text[192];
  std::snprintf(text, sizeof text,
                "circle select: radius %.0f px  (drag: select, Shift+drag or middle button: deselect, wheel: "
                "radius; Enter, Esc or right click ends)",
                radius_);
  status_ = text;
}

void CircleSelectTool::paint(glm::vec2 at, bool add, ToolContext& ctx) {
  const CovarianceMesh& mesh = ctx.document.mesh();
  const Viewport& v = ctx.viewport;
  const auto covered = [&](const Vec3& point) {
    const auto p = visible_pixel(v.camera, v.width, v.height, point);
    return p && glm::length(glm::vec2(*p) - (at + glm::vec2(0.5f))) <= radius_;
  };
  std::vector<int> inside;
  for (size_t i = 0; i < mesh.n_vertices(); ++i)
    if (visible_[i] && covered(mesh.mean(i))) inside.push_back(int(i));
  if (mode_ == SelectMode::edge) {
    const std::vector<EdgeEnds> edges = edges_within(mesh, inside);
    if (add)
      ctx.selection.select_edges(mesh, edges, true);
    else
      ctx.selection.deselect_edges(mesh, edges);
    return;
  }
  if (mode_ == SelectMode::face) {  // the faces whose centre is covered
    std::vector<int> faces;
    for (size_t f = 0; f < mesh.n_faces(); ++f) {
      const std::span<const int> corners = mesh.face(f);
      const bool seen = std::all_of(corners.begin(), corners.end(), [&](int c) { return visible_[size_t(c)]; });
      if (seen && covered(centre_of_vertices(mesh, {corners.begin(), corners.end()}))) faces.push_back(int(f));
    }
    if (add)
      ctx.selection.select_faces(mesh, faces, true);
    else
      ctx.selection.deselect_faces(mesh, faces);
    return;
  }
  if (add)
    ctx.selection.select(inside, true);
  else
    ctx.selection.deselect(inside);
}

ToolResult CircleSelectTool::handle(const InputEvent& e, ToolContext& ctx) {
  const bool key = e.type == InputEvent::Type::key_press;
  if ((key && (e.key == GLFW_KEY_ESCAPE || e.key == GLFW_KEY_ENTER || e.key == GLFW_KEY_KP_ENTER)) ||
      (e.type == InputEvent::Type::press && e.button == 1)) {
    ctx.report("circle select: " + std::to_string(ctx.selection.vertices().size()) + " selected", false);
    return ToolResult::confirmed;
  }
  if (e.type == InputEvent::Type::press && (e.button == 0 || e.button == 2)) {
    painting_ = e.button == 0 && !ctx.shift;
    at_ = e.position;
    paint(at_, *painting_, ctx);
  } else if (e.type == InputEvent::Type::release) {
    painting_.reset();
  } else if (e.type == InputEvent::Type::move) {
    at_ = e.position;
    if (painting_) paint(at_, *painting_, ctx);
  } else if (e.type == InputEvent::Type::scroll) {
    radius_ = std::clamp(radius_ * float(std::pow(1.15, double(e.steps))), 2.0f, 2000.0f);
    describe();
  }
  return ToolResult::consumed;
}

void CircleSelectTool::draw_overlay(ImDrawList& draw, const ToolContext&) const {
  draw.AddCircle(ImVec2(at_.x, at_.y), radius_, IM_COL32(255, 255, 255, 200), 48, 1.5f);
}

}  // namespace gps
