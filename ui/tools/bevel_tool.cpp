// Bevel as a modal tool.
#include "ui/tools/bevel_tool.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/modelling/mesh_queries.h"
#include "core/modelling/operation_words.h"
#include "core/support/error.h"
#include "ui/document/editor_document.h"
#include "ui/editing/selection.h"

namespace gps {

double BevelTool::width_from_cursor(glm::vec2 start, glm::vec2 cursor, glm::vec2 centre, double world_per_pixel) {
  return std::max(0.0, double(glm::length(cursor - centre) - glm::length(start - centre)) * world_per_pixel);
}

std::unique_ptr<ModalTool> BevelTool::start(ToolContext& ctx, bool vertices) {
  const CovarianceMesh& mesh = ctx.document.mesh();
  std::unique_ptr<BevelTool> tool(new BevelTool);
  tool->vertices_ = vertices;
  tool->selected_ = ctx.selection.vertices();
  if (!vertices) {
    tool->edges_ = ctx.selection.edges(mesh);
    if (tool->edges_.empty()) {
      ctx.note("bevel refused: select an edge or more (both ends of each)", true);
      return nullptr;
    }
  } else if (tool->selected_.empty()) {
    ctx.note("bevel vertices refused: select a vertex or more", true);
    return nullptr;
  }
  tool->base_ = std::make_shared<const CovarianceMesh>(mesh);
  tool->centre_ = centre_of_vertices(mesh, tool->selected_);
  tool->start_cursor_ = ctx.cursor;
  tool->options_.width = 0.0;
  tool->update(ctx);
  return tool;
}

void BevelTool::follow(glm::vec2 cursor, const ToolContext& ctx) {
  const Viewport& v = ctx.viewport;
  const auto c = project_to_pixel(v.camera, v.width, v.height, centre_);
  if (!c) return;
  options_.width =
      width_from_cursor(start_cursor_, cursor, glm::vec2(*c), world_per_pixel(v.camera, v.height, centre_));
}

void BevelTool::update(ToolContext& ctx) {
  char amount[128];
  std::snprintf(amount, sizeof amount, "%s: width %.4f%s, %s, profile %s", what(), options_.width,
                typed_.shown().c_str(), count_of(size_t(options_.segments), "segment", "segments").c_str(),
                short_number(options_.profile).c_str());
  const std::string keys =
      "  (move away from the centre or type the width, wheel: segments, P: profile; "
      "click or Enter confirms, Esc cancels)";
  preview(
      ctx, !(options_.width > 0),
      [&] { return vertices_ ? bevel_vertices(*base_, selected_, options_) : bevel_edges(*base_, edges_, options_); },
      amount, keys);
}

ToolResult BevelTool::handle(const InputEvent& e, ToolContext& ctx) {
  if (cancelled_by(e, ctx, what(), "width 0")) return ToolResult::cancelled;
  if (confirms(e)) {  // one undo step: the bevel shown
    if (!install_shown(ctx, what())) return ToolResult::confirmed;
    const bool vertices = vertices_;
    const std::vector<int> selected = selected_;
    const std::vector<std::array<int, 2>> edges = edges_;
    if (ctx.adjustable)
      ctx.adjustable({what(),
                      {{"width", options_.width, 0.0, std::numeric_limits<double>::max()},
                       {"segments", double(options_.segments), 1.0, double(kMaxBevelSegments), true},
                       {"profile", options_.profile, 0.0, 1.0}},
                      base_,
                      [vertices, selected, edges](const CovarianceMesh& before, const std::vector<double>& v) {
                        BevelOptions o;
                        o.width = v[0];
                        o.segments = int(v[1]);
                        o.profile = v[2];
                        return vertices ? bevel_vertices(before, selected, o) : bevel_edges(before, edges, o);
                      }});
    return ToolResult::confirmed;
  }
  const bool key = e.type == InputEvent::Type::key_press;
  if (e.type == InputEvent::Type::move) {
    if (!typed_.empty()) return ToolResult::consumed;
    follow(e.position, ctx);
  } else if (typed_.handle(e)) {
    const double typed = typed_.value();
    if (!std::isfinite(typed) && !typed_.empty()) return ToolResult::consumed;
    if (std::isfinite(typed))
      options_.width = typed;
    else
      follow(ctx.cursor, ctx);  // nothing typed: the mouse's width again
  } else if (e.type == InputEvent::Type::scroll) {
    options_.segments = std::clamp(options_.segments + wheel_.take(e.steps), 1, kMaxBevelSegments);
  } else if (key && e.key == GLFW_KEY_P) {
    options_.profile = options_.profile == 0.5 ? 0.25 : 0.5;
  } else {
    return ToolResult::consumed;
  }
  update(ctx);
  return ToolResult::consumed;
}

}  // namespace gps
