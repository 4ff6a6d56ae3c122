#pragma once
// Spin as a modal tool, as Blender's: the selected chain of edges is spun around the 3D cursor,
// about the view axis (X, Y, Z: a world axis instead), by the angle the mouse turns around the cursor
// or a typed number of degrees, in steps set by the wheel. Each value is spun anew from the mesh
// before (core/modelling/spin.h) and shown in place of the document's; the document changes when
// confirmed, as one undo step. A refusal is shown in the status line, with the mesh before.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ui/tools/preview_tool.h"
#include "ui/tools/typed_number.h"
#include "ui/input/wheel_notches.h"

namespace gps {

class SpinTool : public PreviewTool {
public:
  /// nullptr (the refusal reported) where the selection's edges are not one chain (Selection::edges).
  static std::unique_ptr<ModalTool> start(ToolContext& ctx);

  ToolResult handle(const InputEvent& event, ToolContext& ctx) override;

  static constexpr int kDefaultSteps = 9;  // Blender's

private:
  SpinTool() = default;
  void follow(glm::vec2 cursor, const ToolContext& ctx);
  void update(ToolContext& ctx);

  std::vector<int> profile_;
  std::shared_ptr<const CovarianceMesh> base_;  // the mesh before the spin
  Vec3 centre_ = Vec3::Zero(), view_axis_ = Vec3::UnitZ();
  int axis_ = -1;  // a world axis (0 x, 1 y, 2 z), else the view axis
  glm::vec2 start_cursor_{0.0f};
  double degrees_ = 0.0;
  int steps_ = kDefaultSteps;
  TypedNumber typed_;
  WheelNotches wheel_;
};

}  // namespace gps
