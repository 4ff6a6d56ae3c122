#pragma once
// The editor's modal tools (G / S / R, loop cut, knife, inset, crease, bevel, slide, the gizmo's
// drag) behind one interface: once started, a tool takes the events first until it is confirmed or
// cancelled. It sees the editor only through a ToolContext, so that a new tool is one class and one
// command, and EditorApp holds at most one tool and hands it each event.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh/covariance_mesh.h"
#include "core/modelling/mesh_arrays.h"
#include "core/plans/planned_surface.h"
#include "core/plans/surface_replanner.h"
#include "ui/document/selection_record.h"
#include "ui/editing/adjustable_operation.h"
#include "ui/editing/axis_handles.h"
#include "ui/editing/edit_reach.h"
#include "ui/editing/snap_options.h"
#include "ui/editing/transform_orientation.h"
#include "ui/input/input_events.h"
#include "view/projection.h"

struct ImDrawList;

namespace gps {

class EditorDocument;
class Selection;
class SurfaceReplanner;
class ModalTool;

/// The gizmo a tool draws while it runs (a handle drag's), with the handle it holds lit.
struct ToolGizmo {
  HandleFrame frame;
  Handle lit;
};

/// What a tool did with an event. `confirmed` and `cancelled` end it (it has already changed or
/// restored the document); `replaced` ends it in favour of ToolContext::next.
enum class ToolResult { consumed, passed_on, confirmed, cancelled, replaced };

/// What a tool may use of the editor: its document and selection, the view and the cursor, the
/// reach of an edit, and the editor's ways to show a mesh, apply an operation and report.
struct ToolContext {
  ToolContext(EditorDocument& document, Selection& selection, ReachOptions& reach)
      : document(document), selection(selection), reach(reach) {}

  EditorDocument& document;
  Selection& selection;
  ReachOptions& reach;
  const std::vector<char>* hidden_vertices = nullptr;  // 1: hidden (H), never in an edit's reach
  Viewport viewport;
  glm::vec2 cursor{0.0f};
  bool shift = false, ctrl = false;
  bool transform_gaussians = true;  // G / S / R carry the Gaussians (else the positions only)
  SnapOptions snap;
  /// What an axis key takes first in G / S / R (ui/editing/transform_orientation.h).
  TransformOrientation orientation = TransformOrientation::global;
  Vec3 cursor_point = Vec3::Zero();  // the 3D cursor
  /// The limit surface's point under a window pixel in the last frame drawn; nullopt on the background.
  std::function<std::optional<Vec3>(glm::vec2 pixel)> surface_at;

  /// Replaces the document's mesh by `result` as one undo step; throws gps::Error before anything changes.
  /// `replanner`: the plans of the document's topology with other sharpness (core/plans/surface_replanner.h).
  std::function<void(const Modelled& result, SurfaceReplanner* replanner)> install;
  /// run() on the document's mesh installed as one undo step, its summary or refusal reported as
  /// "NAME: summary"; false when refused (nothing changed).
  std::function<bool(const std::string& name, const std::function<Modelled(const CovarianceMesh&)>& run,
                     SurfaceReplanner* replanner)>
      operate;
  /// The summary of the operation installed last, as installed (the mirror modifier may have left
  /// faces out of it).
  std::function<std::string()> last_summary;
  /// Shows `mesh` in place of the document's (its surface, cage and creases), `selected` drawn as the
  /// selection; `surface`: its plans (else planned anew). Throws gps::Error where it cannot be planned.
  std::function<void(std::shared_ptr<const CovarianceMesh> mesh, const std::vector<int>& selected,
                     std::optional<ReplannedTables> surface)>
      show_preview;
  /// Shows the document's mesh again (`surface`: its plans, else planned anew); a failure is reported.
  std::function<void(std::optional<ReplannedTables> surface)> show_document;
  /// The document's mesh was replaced outside install (an undone step): rebuilds for it, with `selection`.
  std::function<void(const SelectionRecord& selection)> rebuild;
  /// A message in the status line, printed (and, with `note`, in the Inspector too); `show_status`
  /// only shows it.
  std::function<void(const std::string&message, bool error)> report, note, show_status;
  /// After a confirmed operation: what the Adjust last operation panel (F9) may make again.
  std::function<void(AdjustableOperation operation)> adjustable;
  /// The plans the view asks for (a tool's replanner is made with them).
  PlanOptions plans;

  /// A tool that ends with ToolResult::replaced sets the tool that takes over.
  std::unique_ptr<ModalTool> next;
};

class ModalTool {
public:
  virtual ~ModalTool() = default;
  /// Takes one event (ctx.cursor already where it leaves the pointer).
  virtual ToolResult handle(const InputEvent& event, ToolContext& ctx) = 0;
  /// What the tool is doing, for the status bar; an error where `error()`.
  const std::string& status() const { return status_; }
  bool error() const { return error_; }
  /// Draws over the surface (a loop cut's ring); nothing by default.
  virtual void draw_overlay(ImDrawList& draw, const ToolContext& ctx) const {
    (void)draw;
    (void)ctx;
  }
  /// The gizmo to draw in `view` in place of the selection's; none by default.
  virtual std::optional<ToolGizmo> gizmo(const Viewport& view) const {
    (void)view;
    return std::nullopt;
  }
  /// How many vertices the tool's edit reaches (its proportional reach included), for the
  /// statistics; 0 for a tool that does not edit Gaussians.
  virtual size_t reached() const { return 0; }

protected:
  std::string status_;  // what status() shows, kept by each tool as it goes
  bool error_ = false;
};

/// Enter (either one) or a left click: what confirms a tool.
bool confirms(const InputEvent& event);
/// Esc or a right click: what cancels a tool.
bool cancels(const InputEvent& event);

}  // namespace gps
