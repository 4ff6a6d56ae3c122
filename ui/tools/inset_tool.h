#pragma once
// The inset (I) as a modal tool: the selected faces inset (core/modelling/inset.h) by a thickness
// followed from the mouse (how much nearer the faces' centre it is than where it started) or typed;
// the first thickness installs the inset, later ones change its Gaussians in place, all recomputed
// from the mesh before it; one undo step when confirmed, Esc restores the mesh before. Once confirmed,
// F9 adjusts its thickness and depth (the inner faces raised along the region's normal, as Blender's).
#include <memory>
#include <string>
#include <vector>

#include "ui/tools/modal_tool.h"
#include "ui/tools/typed_number.h"

namespace gps {

class InsetTool : public ModalTool {
public:
  /// nullptr (the refusal reported) where the selection holds no face.
  static std::unique_ptr<ModalTool> start(ToolContext& ctx);

  ToolResult handle(const InputEvent& event, ToolContext& ctx) override;

private:
  InsetTool() = default;
  void update(double thickness, ToolContext& ctx);
  void follow(glm::vec2 cursor, ToolContext& ctx);
  void end(bool keep, ToolContext& ctx);

  std::shared_ptr<const CovarianceMesh> base_;
  std::vector<int> faces_;
  SelectionRecord selection_before_;
  Vec3 centre_ = Vec3::Zero();
  glm::vec2 start_cursor_{0.0f};
  TypedNumber typed_;
  bool applied_ = false;
  double thickness_ = 0.0;  // the inset shown
  std::string summary_;
};

}  // namespace gps
