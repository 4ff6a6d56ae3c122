#pragma once
// Bevel (Ctrl+B edges, Ctrl+Shift+B vertices) as a modal tool, as Blender's: the width follows the
// cursor's distance from the selection's centre (how much farther it is than where it started) or a
// typed number, the wheel sets the segments and P the profile (round 0.5 or straight 0.25). Each
// value is bevelled anew from the mesh before (core/modelling/bevel.h) and shown in place of the
// document's; the document changes when confirmed, as one undo step. A refusal is shown in the
// status line, with the mesh before.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/modelling/bevel.h"
#include "ui/tools/preview_tool.h"
#include "ui/tools/typed_number.h"
#include "ui/input/wheel_notches.h"

namespace gps {

class BevelTool : public PreviewTool {
public:
  /// `vertices`: bevels the selected vertices, else the selected edges (Selection::edges).
  /// nullptr (the refusal reported) where the selection holds none.
  static std::unique_ptr<ModalTool> start(ToolContext& ctx, bool vertices);

  ToolResult handle(const InputEvent& event, ToolContext& ctx) override;

  /// The width after the cursor moved from `start` to `cursor`, the selection's centre at pixel
  /// `centre`, `world_per_pixel` there: the gain in distance from the centre, never below 0.
  static double width_from_cursor(glm::vec2 start, glm::vec2 cursor, glm::vec2 centre, double world_per_pixel);

private:
  BevelTool() = default;
  const char* what() const { return vertices_ ? "bevel vertices" : "bevel"; }
  void follow(glm::vec2 cursor, const ToolContext& ctx);
  void update(ToolContext& ctx);

  bool vertices_ = false;
  std::vector<int> selected_;
  std::vector<std::array<int, 2>> edges_;
  std::shared_ptr<const CovarianceMesh> base_;  // the mesh before the bevel
  Vec3 centre_ = Vec3::Zero();
  glm::vec2 start_cursor_{0.0f};
  BevelOptions options_;
  TypedNumber typed_;
  WheelNotches wheel_;
};

}  // namespace gps
