#include "ui/tools/preview_tool.h"

#include <memory>

#include "core/support/error.h"

namespace gps {

void PreviewTool::preview(ToolContext& ctx, bool none, const std::function<Modelled()>& make, const std::string& amount,
                          const std::string& keys) {
  try {
    if (!none) {
      Modelled made = make();
      ctx.show_preview(std::make_shared<const CovarianceMesh>(made.mesh), made.selection, std::nullopt);
      result_ = std::move(made);
    } else if (result_) {
      ctx.show_document(std::nullopt);
      result_.reset();
    }
    status_ = amount + keys;
    error_ = false;
  } catch (const Error& e) {  // refused: the mesh before
    if (result_) {
      result_.reset();
      ctx.show_document(std::nullopt);
    }
    refusal_ = e.what();
    status_ = amount + ": " + refusal_;
    error_ = true;
  }
}

bool PreviewTool::cancelled_by(const InputEvent& e, ToolContext& ctx, const std::string& name,
                               const std::string& nothing) {
  if (!cancels(e) && !(confirms(e) && !result_)) return false;
  if (result_) ctx.show_document(std::nullopt);
  ctx.report(cancels(e) ? name + " cancelled" : name + ": nothing done (" + (error_ ? refusal_ : nothing) + ")",
             error_ && !cancels(e));
  return true;
}

bool PreviewTool::install_shown(ToolContext& ctx, const std::string& name) {
  const Modelled shown = *result_;  // made from the document's mesh as it is
  if (ctx.operate(
          name, [&](const CovarianceMesh&) { return shown; }, nullptr))
    return true;
  ctx.show_document(std::nullopt);
  return false;
}

}  // namespace gps
