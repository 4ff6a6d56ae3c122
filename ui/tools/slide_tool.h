#pragma once
// Edge and vertex slide (G G, as Blender's) as a modal tool: selected edges slide along the edges
// beside them (core/modelling/slide.h edge_slide), a single selected vertex along its edge to the
// neighbour the cursor moves toward (vertex_slide). The mouse sets the factor, as far along the
// screen as the slide at factor ±1 (or 1) carries the selection, or a typed number does; each value
// is recomputed from the mesh before the slide. One undo step when confirmed, Esc restores the mesh.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ui/tools/modal_tool.h"
#include "ui/tools/typed_number.h"

namespace gps {

class SlideTool : public ModalTool {
public:
  /// nullptr (the refusal reported) where the selection holds no edge and is not one vertex, or
  /// where its edges cannot slide to either side.
  static std::unique_ptr<ModalTool> start(ToolContext& ctx);

  ToolResult handle(const InputEvent& event, ToolContext& ctx) override;

private:
  SlideTool() = default;
  void follow(glm::vec2 cursor, const ToolContext& ctx);
  void update(double factor, ToolContext& ctx);

  std::shared_ptr<const CovarianceMesh> base_;  // the mesh before the slide
  std::vector<std::array<int, 2>> edges_;       // an edge slide's (empty: a vertex slide)
  // An edge slide: the selection's centre before it and at factor +1 and −1 (nullopt: that side refused).
  Vec3 centre_ = Vec3::Zero();
  std::optional<Vec3> plus_, minus_;
  // A vertex slide: the vertex, its neighbours and the one it slides toward (−1: none yet).
  int vertex_ = -1, toward_ = -1;
  std::vector<int> neighbours_;
  glm::vec2 start_cursor_{0.0f};
  TypedNumber typed_;
  double factor_ = 0.0;
  std::string refusal_;  // refusal_: why the value shown cannot slide
};

}  // namespace gps
