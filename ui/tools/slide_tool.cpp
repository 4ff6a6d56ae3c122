// Edge and vertex slide as a modal tool.
#include "ui/tools/slide_tool.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/modelling/mesh_queries.h"
#include "core/modelling/slide.h"
#include "core/support/error.h"
#include "ui/document/editor_document.h"
#include "ui/editing/selection.h"

namespace gps {

namespace {

std::optional<glm::vec2> pixel_at(const Viewport& v, const Vec3& p) {
  const auto q = project_to_pixel(v.camera, v.width, v.height, p);
  return q ? std::optional<glm::vec2>(glm::vec2(*q)) : std::nullopt;
}

// How far along `to` − `from` (window pixels) the cursor's move `moved` reaches, as a fraction; 0 for
// a step under a pixel.
double fraction_along(glm::vec2 moved, glm::vec2 from, glm::vec2 to) {
  const glm::vec2 d = to - from;
  return glm::dot(d, d) < 1.0f ? 0.0 : double(glm::dot(moved, d) / glm::dot(d, d));
}

}  // namespace

std::unique_ptr<ModalTool> SlideTool::start(ToolContext& ctx) {
  const CovarianceMesh& mesh = ctx.document.mesh();
  const std::vector<int> selected = ctx.selection.vertices();
  std::unique_ptr<SlideTool> tool(new SlideTool);
  tool->base_ = std::make_shared<const CovarianceMesh>(mesh);
  tool->edges_ = ctx.selection.edges(mesh);
  tool->start_cursor_ = ctx.cursor;
  if (!tool->edges_.empty()) {
    tool->centre_ = centre_of_vertices(mesh, selected);
    std::string refusal;
    for (const double side : {1.0, -1.0}) {
      try {
        const Modelled slid = edge_slide(mesh, tool->edges_, side);
        (side > 0 ? tool->plus_ : tool->minus_) = centre_of_vertices(slid.mesh, selected);
      } catch (const Error& e) {
        refusal = e.what();
      }
    }
    if (!tool->plus_ && !tool->minus_) {
      ctx.note("edge slide refused: " + refusal, true);
      return nullptr;
    }
  } else if (selected.size() == 1) {
    tool->vertex_ = selected.front();
    const MeshConnectivity& c = mesh.connectivity();
    const int v = tool->vertex_;
    for (int k = c.vertex_edge_offsets[size_t(v)]; k < c.vertex_edge_offsets[size_t(v) + 1]; ++k)
      tool->neighbours_.push_back(c.other_vertex(c.vertex_edges[size_t(k)], v));
    if (tool->neighbours_.empty()) {
      ctx.note("vertex slide refused: vertex " + std::to_string(tool->vertex_) + " has no edge", true);
      return nullptr;
    }
  } else {
    ctx.note("slide refused: select edges (both ends of each) or one vertex", true);
    return nullptr;
  }
  ctx.document.begin_edit();
  tool->update(0.0, ctx);
  return tool;
}

void SlideTool::follow(glm::vec2 cursor, const ToolContext& ctx) {
  const Viewport& v = ctx.viewport;
  const glm::vec2 moved = cursor - start_cursor_;
  if (vertex_ >= 0) {  // toward the neighbour whose direction on screen is nearest the cursor's move
    const auto from = pixel_at(v, base_->mean(size_t(vertex_)));
    if (!from || glm::length(moved) < 1.0f) return;
    double best = -2.0;
    for (const int u : neighbours_) {
      const auto to = pixel_at(v, base_->mean(size_t(u)));
      if (!to || glm::length(*to - *from) < 1.0f) continue;
      const double cosine = double(glm::dot(glm::normalize(*to - *from), glm::normalize(moved)));
      if (cosine > best) best = cosine, toward_ = u, factor_ = std::clamp(fraction_along(moved, *from, *to), 0.0, 1.0);
    }
    return;
  }
  const auto from = pixel_at(v, centre_);
  if (!from) return;
  const auto plus = plus_ ? pixel_at(v, *plus_) : std::nullopt;
  const auto minus = minus_ ? pixel_at(v, *minus_) : std::nullopt;
  const double forward = plus ? fraction_along(moved, *from, *plus) : 0.0,
               back = minus ? fraction_along(moved, *from, *minus) : 0.0;
  factor_ = forward > 0 ? std::min(forward, 1.0) : back > 0 ? -std::min(back, 1.0) : 0.0;
}

void SlideTool::update(double factor, ToolContext& ctx) {
  const char* what = vertex_ >= 0 ? "vertex slide" : "edge slide";
  try {
    Modelled slid;
    if (vertex_ < 0)
      slid = edge_slide(*base_, edges_, factor);
    else
      slid = vertex_slide(*base_, vertex_, toward_ >= 0 ? toward_ : neighbours_.front(), factor);
    ctx.document.set_gaussians(slid.mesh);
    char text[160];
    std::snprintf(text, sizeof text, "%s: %.3f%s (move the mouse or type %s; click or Enter confirms, Esc cancels)",
                  what, factor, typed_.shown().c_str(), vertex_ >= 0 ? "0 to 1" : "-1 to 1");
    status_ = text;
    error_ = false;
  } catch (const Error& e) {  // the mesh as before the slide
    ctx.document.set_gaussians(*base_);
    refusal_ = e.what();
    status_ = std::string(what) + typed_.shown() + ": " + refusal_;
    error_ = true;
  }
}

ToolResult SlideTool::handle(const InputEvent& e, ToolContext& ctx) {
  const char* what = vertex_ >= 0 ? "vertex slide" : "edge slide";
  if (cancels(e)) {
    ctx.document.cancel_edit();
    ctx.report(std::string(what) + " cancelled", false);
    return ToolResult::cancelled;
  }
  if (confirms(e)) {
    if (error_) {
      ctx.document.cancel_edit();
      ctx.report(std::string(what) + " refused: " + refusal_, true);
      return ToolResult::cancelled;
    }
    char text[64];
    std::snprintf(text, sizeof text, "%s %.3f", what, factor_);
    ctx.document.commit_edit();
    ctx.note(text, false);
    return ToolResult::confirmed;
  }
  if (e.type == InputEvent::Type::move && typed_.empty()) {
    follow(e.position, ctx);
    update(factor_, ctx);
  } else if (typed_.handle(e)) {
    const double typed = typed_.value();
    if (std::isfinite(typed)) factor_ = typed;
    if (std::isfinite(typed) || typed_.empty()) update(factor_, ctx);
  } else if (e.type == InputEvent::Type::scroll) {
    return ToolResult::passed_on;
  }
  return ToolResult::consumed;
}

}  // namespace gps
