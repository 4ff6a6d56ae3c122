// The crease and corner tool as a modal tool.
#include "ui/tools/sharpness_tool.h"

#include <algorithm>
#include <cmath>

#include "core/mesh/sharpness.h"
#include "core/support/error.h"
#include "ui/document/editor_document.h"
#include "ui/editing/crease_tool.h"
#include "ui/editing/selection.h"

namespace gps {

std::unique_ptr<ModalTool> SharpnessTool::start(ToolContext& ctx, bool corners) {
  const CovarianceMesh& mesh = ctx.document.mesh();
  const std::vector<int>& selected = ctx.selection.vertices();
  const auto edges = ctx.selection.edges(mesh);
  if (!corners && edges.empty()) {
    ctx.note("crease refused: select an edge or more (both ends of each)", true);
    return nullptr;
  }
  std::unique_ptr<SharpnessTool> tool(new SharpnessTool);
  tool->corners_ = corners;
  tool->selected_ = ctx.selection;
  const double common = corners ? common_corner(mesh, selected) : common_crease(mesh, edges);
  tool->start_ = std::isfinite(common) ? std::min(common, kInfiniteSharpness) : 0.0;
  tool->value_ = tool->start_;
  tool->start_cursor_ = ctx.cursor;
  tool->shown_ = std::make_shared<const CovarianceMesh>(mesh);
  tool->preview(tool->start_, ctx);
  return tool;
}

ReplannedTables SharpnessTool::surface(const CovarianceMesh& mesh, const ToolContext& ctx) {
  if (replanner_)
    replanner_->set_sharpness(mesh.sharpness);
  else
    replanner_ = std::make_unique<SurfaceReplanner>(mesh.topology(), ctx.plans, mesh.sharpness);
  return replanner_->replanned();
}

// Re-plans the surface for the sharpness (a change of sharpness changes the plans, as a change of
// topology does); the document keeps its mesh until the tool is confirmed.
void SharpnessTool::preview(double sharpness, ToolContext& ctx) {
  try {
    if (sharpness != value_) {
      auto shown = std::make_shared<const CovarianceMesh>(
          sharpened_selection(ctx.document.mesh(), selected_, corners_, sharpness, ctx.reach).mesh);
      ctx.show_preview(shown, selected_.vertices(), surface(*shown, ctx));
      shown_ = std::move(shown);
      value_ = sharpness;
    }
    status_ = std::string(what()) + ": " + sharpness_text(sharpness) + typed_.shown() +
              "  (drag left/right or type 0-10, 10 = ∞; click or Enter confirms, Esc cancels)";
    error_ = false;
  } catch (const Error& e) {
    status_ = std::string(what()) + typed_.shown() + ": " + e.what();
    error_ = true;
  }
}

void SharpnessTool::end(bool keep, ToolContext& ctx) {
  if (keep && shown_->sharpness != ctx.document.mesh().sharpness) {  // one undo step
    const double value = value_;
    if (ctx.operate(
            what(),
            [&](const CovarianceMesh& m) { return sharpened_selection(m, selected_, corners_, value, ctx.reach); },
            replanner_.get()))
      ctx.selection = selected_;  // the selection as it was (set_crease selects the edges' ends)
    return;
  }
  try {  // the surface planned for the document's sharpness again
    if (replanner_)
      ctx.show_document(surface(ctx.document.mesh(), ctx));
    else
      ctx.show_document(std::nullopt);
  } catch (const Error& e) {
    ctx.report(e.what(), true);
    return;
  }
  ctx.report(keep ? std::string(what()) + ": nothing changed" : std::string(what()) + " cancelled", false);
}

ToolResult SharpnessTool::handle(const InputEvent& e, ToolContext& ctx) {
  if (confirms(e) || cancels(e)) {
    const bool keep = confirms(e);
    end(keep, ctx);
    return keep ? ToolResult::confirmed : ToolResult::cancelled;
  }
  if (e.type == InputEvent::Type::move && typed_.empty()) {
    preview(sharpness_after_drag(start_, e.position.x - start_cursor_.x, float(ctx.viewport.width)), ctx);
  } else if (typed_.handle(e)) {
    const double typed = typed_.value();
    if (std::isfinite(typed))
      preview(typed, ctx);
    else if (e.type != InputEvent::Type::text)  // Backspace to nothing valid: the value it started with
      preview(start_, ctx);
  } else if (e.type == InputEvent::Type::scroll) {
    return ToolResult::passed_on;
  }
  return ToolResult::consumed;
}

}  // namespace gps
