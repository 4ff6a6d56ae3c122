#pragma once
// The sharpen/soften brush as a modal tool (ui/editing/covariance_brush.h): a circle follows the
// surface under the pointer, its radius at first the mean edge length; dragging with the left button
// paints dabs (Shift held: the other kind), the wheel sets the radius and typed digits the strength
// (0.5 at first). Enter keeps the strokes as one undo step, Escape or a right click takes them back.
#include <memory>
#include <optional>
#include <set>

#include "ui/editing/covariance_brush.h"
#include "ui/tools/modal_tool.h"
#include "ui/tools/typed_number.h"

namespace gps {

class BrushTool : public ModalTool {
public:
  /// nullptr (the refusal reported) for a mesh without vertices.
  static std::unique_ptr<ModalTool> start(ToolContext& ctx, BrushKind kind);

  ToolResult handle(const InputEvent& event, ToolContext& ctx) override;
  void draw_overlay(ImDrawList& draw, const ToolContext& ctx) const override;

private:
  BrushTool() = default;
  void dab(ToolContext& ctx);
  void describe(const ToolContext& ctx);
  BrushKind kind_now(const ToolContext& ctx) const;  // Shift held: the other kind

  BrushKind kind_ = BrushKind::sharpen;
  double radius_ = 1.0, strength_ = 0.5;
  bool painting_ = false;
  size_t dabs_ = 0;
  std::set<int> touched_;
  std::optional<Vec3> hover_;  // the surface point under the pointer (none: background)
  TypedNumber typed_;
};

}  // namespace gps
