// The sharpen/soften brush as a modal tool.
#include "ui/tools/brush_tool.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/modelling/operation_words.h"
#include "ui/document/editor_document.h"
#include "ui/editing/covariance_presets.h"

namespace gps {

namespace {

const char* brush_name(BrushKind kind) { return kind == BrushKind::sharpen ? "sharpen" : "soften"; }

}  // namespace

std::unique_ptr<ModalTool> BrushTool::start(ToolContext& ctx, BrushKind kind) {
  const CovarianceMesh& mesh = ctx.document.mesh();
  if (mesh.n_vertices() == 0) {
    ctx.note(std::string(brush_name(kind)) + " brush refused: the mesh has no vertices", true);
    return nullptr;
  }
  std::unique_ptr<BrushTool> tool(new BrushTool);
  tool->kind_ = kind;
  // At first the mean edge length: a dab reaches the corners of the faces under it.
  double length = 0.0;
  for (size_t e = 0; e < mesh.n_edges(); ++e)
    length += (mesh.mean(size_t(mesh.edge(e)[0])) - mesh.mean(size_t(mesh.edge(e)[1]))).norm();
  tool->radius_ = mesh.n_edges() > 0 && length > 0 ? length / double(mesh.n_edges()) : 1.0;
  ctx.document.begin_edit();
  tool->hover_ = ctx.surface_at(ctx.cursor);
  tool->describe(ctx);
  return tool;
}

BrushKind BrushTool::kind_now(const ToolContext& ctx) const {
  if (!ctx.shift) return kind_;
  return kind_ == BrushKind::sharpen ? BrushKind::soften : BrushKind::sharpen;
}

void BrushTool::dab(ToolContext& ctx) {
  if (!hover_) return;
  const BrushKind kind = kind_now(ctx);
  const CovarianceMesh& mesh = ctx.document.mesh();
  const std::vector<BrushedVertex> reached = brush_reach(mesh, *hover_, radius_, strength_);
  for (const BrushedVertex& r : reached) {
    const Mat3 brushed =
        brushed_covariance(mesh.covariance(size_t(r.vertex)), vertex_normal(mesh, r.vertex), r.weight, kind);
    ctx.document.set_covariance(r.vertex, brushed);
    touched_.insert(r.vertex);
  }
  if (!reached.empty()) ++dabs_;
}

void BrushTool::describe(const ToolContext& ctx) {
  char text[256];
  std::snprintf(text, sizeof text,
                "%s brush: radius %.4g, strength %s%s, %s on %s  (drag on the surface to paint, Shift: %s; "
                "wheel: radius, digits: strength; Enter keeps, Esc takes back)",
                brush_name(kind_now(ctx)), radius_, short_number(strength_).c_str(), typed_.shown().c_str(),
                count_of(dabs_, "dab", "dabs").c_str(), count_of(touched_.size(), "vertex", "vertices").c_str(),
                brush_name(kind_now(ctx) == BrushKind::sharpen ? BrushKind::soften : BrushKind::sharpen));
  status_ = text;
  error_ = false;
}

ToolResult BrushTool::handle(const InputEvent& e, ToolContext& ctx) {
  const bool key = e.type == InputEvent::Type::key_press;
  if (cancels(e)) {
    ctx.document.cancel_edit();
    ctx.report(std::string(brush_name(kind_)) + " brush: strokes taken back", false);
    return ToolResult::cancelled;
  }
  if (key && (e.key == GLFW_KEY_ENTER || e.key == GLFW_KEY_KP_ENTER)) {
    const bool changed = ctx.document.commit_edit();
    ctx.report(std::string(brush_name(kind_)) + " brush: " + count_of(dabs_, "dab", "dabs") + " changed " +
                   count_of(changed ? touched_.size() : 0, "Gaussian", "Gaussians"),
               false);
    return ToolResult::confirmed;
  }
  if (e.type == InputEvent::Type::press && e.button == 0) {
    painting_ = true;
    hover_ = ctx.surface_at(e.position);
    dab(ctx);
  } else if (e.type == InputEvent::Type::release && e.button == 0) {
    painting_ = false;
  } else if (e.type == InputEvent::Type::move) {
    hover_ = ctx.surface_at(e.position);
    if (painting_) dab(ctx);
  } else if (e.type == InputEvent::Type::scroll) {
    radius_ *= std::pow(1.15, double(e.steps));
  } else if (typed_.handle(e)) {
    if (std::isfinite(typed_.value())) strength_ = std::clamp(typed_.value(), 0.0, 1.0);
  } else if (!(key || e.type == InputEvent::Type::key_release)) {
    return ToolResult::consumed;
  }
  describe(ctx);
  return ToolResult::consumed;
}

void BrushTool::draw_overlay(ImDrawList& draw, const ToolContext& ctx) const {
  if (!hover_) return;
  const Viewport& v = ctx.viewport;
  const auto at = project_to_pixel(v.camera, v.width, v.height, *hover_);
  if (!at) return;
  const float pixels = float(radius_ / world_per_pixel(v.camera, v.height, *hover_));
  const ImU32 colour = kind_now(ctx) == BrushKind::sharpen ? IM_COL32(255, 170, 60, 255) : IM_COL32(120, 200, 255, 255);
  draw.AddCircle(ImVec2(at->x, at->y), pixels, colour, 48, 2.0f);
  draw.AddCircleFilled(ImVec2(at->x, at->y), 2.0f, colour);
}

}  // namespace gps
