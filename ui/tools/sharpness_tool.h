#pragma once
// The crease tool (Shift+E) and the corner tool (Ctrl+Shift+V) as a modal tool: the sharpness of the
// selected edges, or the corner sharpness of the selected vertices, followed from a horizontal drag
// or typed (ui/editing/crease_tool.h's values); the surface is re-planned for each value shown, only
// around the changed edges or corners (core/plans/surface_replanner.h), and the document changes
// when confirmed, as one undo step.
#include <memory>
#include <string>
#include <vector>

#include "core/plans/surface_replanner.h"
#include "ui/editing/selection.h"
#include "ui/tools/modal_tool.h"
#include "ui/tools/typed_number.h"

namespace gps {

class SharpnessTool : public ModalTool {
public:
  /// `corners`: the vertices' corner sharpness, else the selected edges' (in edge mode those
  /// selected as edges, else those with both ends selected). nullptr (the refusal reported) for
  /// edges where the selection holds none.
  static std::unique_ptr<ModalTool> start(ToolContext& ctx, bool corners);

  ToolResult handle(const InputEvent& event, ToolContext& ctx) override;

private:
  SharpnessTool() = default;
  const char* what() const { return corners_ ? "corner" : "crease"; }
  ReplannedTables surface(const CovarianceMesh& mesh, const ToolContext& ctx);  // its plans and their change
  void preview(double sharpness, ToolContext& ctx);
  void end(bool keep, ToolContext& ctx);

  bool corners_ = false;
  Selection selected_;  // the selection it started with: its edges, or its vertices' corners
  double start_ = 0.0, value_ = 0.0;
  glm::vec2 start_cursor_{0.0f};
  TypedNumber typed_;
  std::shared_ptr<const CovarianceMesh> shown_;  // the mesh the surface was planned for
  // The plans of the document's topology, re-planned for each value; made at the first change.
  std::unique_ptr<SurfaceReplanner> replanner_;
};

}  // namespace gps
