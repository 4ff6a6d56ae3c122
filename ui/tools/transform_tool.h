#pragma once
// Blender's G / S / R as a modal tool (the math is ui/editing/transform_mode.h): the selected
// Gaussians follow the mouse or a typed value, with the axis constraints, the proportional and
// mirrored reach and the wheel setting the radius; one undo step when confirmed. The move after an
// extrusion is the same tool along the extrusion's normal, folded into the extrusion's undo step, and
// the move after a duplication (Shift+D) likewise, free.
// G pressed again during a grab hands over to the slide (ui/tools/slide_tool.h), as Blender's G G.
// Snapping (ui/editing/snap_options.h; held Ctrl inverts it) rounds the amount to increments or takes
// the pivot onto the vertex, edge or face under the pointer, marked by a circle.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ui/editing/edit_reach.h"
#include "ui/editing/transform_mode.h"
#include "ui/tools/modal_tool.h"
#include "ui/tools/typed_number.h"

namespace gps {

class TransformTool : public ModalTool {
public:
  /// G / S / R of the selection about `pivot` (the selection must not be empty).
  TransformTool(TransformKind kind, TransformPivot pivot, ToolContext& ctx);
  /// Extrudes the selection (core/modelling/extrude.h) as one undo step, then moves the new vertices
  /// along the extruded faces' normal (free for edges and vertices); nullptr where refused (reported).
  static std::unique_ptr<ModalTool> extrude(ToolContext& ctx);
  /// Duplicates the selected faces (core/modelling/duplicate.h) as one undo step, then moves the copy
  /// freely, as Blender's Shift+D; nullptr where refused (reported).
  static std::unique_ptr<ModalTool> duplicate(ToolContext& ctx);

  ToolResult handle(const InputEvent& event, ToolContext& ctx) override;
  void draw_overlay(ImDrawList& draw, const ToolContext& ctx) const override;
  size_t reached() const override { return reach_.size(); }

private:
  // make(mesh, offset): the operation ("extrude", "duplicate") with its result moved by `offset`.
  using MadeWithOffset = std::function<Modelled(const CovarianceMesh& mesh, const Vec3& offset)>;
  // The move after `operation` ("extrude", "duplicate"), along `normal` (free where zero).
  TransformTool(ToolContext& ctx, const Vec3& normal, std::string operation, std::string summary);
  // make() unmoved as one undo step named `name`, then the move of the selection it leaves (along
  // the normal of the faces within it where `along_normal`) folded into that step, adjustable by F9
  // once ended; nullptr where refused.
  static std::unique_ptr<ModalTool> move_after(ToolContext& ctx, const std::string& name, MadeWithOffset make,
                                               bool along_normal);
  // After the move: the operation and its move adjustable by F9 (the offset along the normal, or the move).
  void make_adjustable(const Vec3& moved, ToolContext& ctx) const;
  void update(ToolContext& ctx);
  void follow(glm::vec2 cursor, ToolContext& ctx);  // the mouse's amount, snapped where snapping is on
  void end(bool keep, ToolContext& ctx);

  std::optional<TransformMode> transform_;
  std::vector<ReachedVertex> reach_;  // the vertices it changes, and how strongly
  TypedNumber typed_;
  bool folds_ = false;  // the move after an extrusion or a duplication: confirmed into its undo step
  std::string operation_, operation_summary_;
  Vec3 normal_ = Vec3::Zero();                    // the move's direction after an extrusion (zero: free)
  std::shared_ptr<const CovarianceMesh> before_;  // the mesh before the operation the move follows
  MadeWithOffset make_;                           // that operation, for F9
  std::optional<SnapPoint> snapped_;              // the element a grab is snapped to
};

}  // namespace gps
