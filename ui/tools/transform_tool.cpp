// G / S / R and the move after an extrusion as a modal tool.
#include "ui/tools/transform_tool.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/modelling/affine_transform.h"
#include "core/modelling/duplicate.h"
#include "core/modelling/extrude.h"
#include "core/modelling/mesh_queries.h"
#include "core/modelling/operation_words.h"
#include "ui/document/editor_document.h"
#include "ui/editing/selection.h"
#include "ui/tools/slide_tool.h"

namespace gps {

namespace {

std::vector<Vec3> start_means(const EditorDocument& document) {
  std::vector<Vec3> means(document.mesh().n_vertices());
  for (size_t v = 0; v < means.size(); ++v) means[v] = document.start_mean(int(v));
  return means;
}

// The Normal orientation of what is selected: in face mode the faces held, in edge mode the edges.
Mat3 selection_normal_frame(const ToolContext& ctx) {
  const CovarianceMesh& mesh = ctx.document.mesh();
  return normal_frame(mesh, ctx.selection.vertices(), ctx.selection.faces(mesh), ctx.selection.edges(mesh));
}

}  // namespace

TransformTool::TransformTool(TransformKind kind, TransformPivot pivot, ToolContext& ctx) {
  ctx.document.begin_edit();
  transform_.emplace(kind, ctx.document.mesh(), ctx.selection.vertices(), ctx.selection.active(), pivot, ctx.viewport,
                     ctx.cursor, ctx.cursor_point);
  transform_->set_orientations(ctx.orientation, selection_normal_frame(ctx));
  reach_ = edit_reach(start_means(ctx.document), transform_->vertices(), ctx.reach, ctx.hidden_vertices);
  update(ctx);
}

TransformTool::TransformTool(ToolContext& ctx, const Vec3& normal, std::string operation, std::string summary)
    : folds_(true), operation_(std::move(operation)), operation_summary_(std::move(summary)) {
  ctx.document.begin_edit();
  transform_.emplace(TransformKind::grab, ctx.document.mesh(), ctx.selection.vertices(), ctx.selection.active(),
                     TransformPivot::median, ctx.viewport, ctx.cursor);
  transform_->set_orientations(ctx.orientation, selection_normal_frame(ctx));
  if (normal != Vec3::Zero()) transform_->constrain_direction(normal, "the normal");
  // The move is of the new vertices only (their copies lie under them).
  for (size_t i = 0; i < transform_->vertices().size(); ++i)
    reach_.push_back({transform_->vertices()[i], 1.0, i, false});
  update(ctx);
}

std::unique_ptr<ModalTool> TransformTool::move_after(ToolContext& ctx, const std::string& name, MadeWithOffset make,
                                                     bool along_normal) {
  auto before = std::make_shared<const CovarianceMesh>(ctx.document.mesh());
  const bool done = ctx.operate(
      name, [&](const CovarianceMesh& m) { return make(m, Vec3::Zero()); }, nullptr);
  if (!done) return nullptr;
  const std::string summary = ctx.last_summary ? ctx.last_summary() : std::string();
  // The area-weighted normal of the faces made (Newell's sums); zero for edges and vertices.
  Vec3 normal = Vec3::Zero();
  if (along_normal) {
    const MeshArrays arrays = arrays_of(ctx.document.mesh());
    for (const int f : ctx.selection.faces(ctx.document.mesh())) normal += newell_normal(arrays, f);
    if (normal.norm() > 0) normal.normalize();
  }
  std::unique_ptr<TransformTool> tool(new TransformTool(ctx, normal, name, summary));
  tool->normal_ = normal;
  tool->before_ = std::move(before);
  tool->make_ = std::move(make);
  return tool;
}

std::unique_ptr<ModalTool> TransformTool::extrude(ToolContext& ctx) {
  if (ctx.selection.holds_faces()) {  // face mode: the faces selected, not every face among their corners
    const std::vector<int> faces = ctx.selection.faces(ctx.document.mesh());
    return move_after(
        ctx, "extrude",
        [faces](const CovarianceMesh& m, const Vec3& offset) { return extrude_faces_by(m, faces, offset); }, true);
  }
  const std::vector<int> selected = ctx.selection.vertices();
  return move_after(
      ctx, "extrude",
      [selected](const CovarianceMesh& m, const Vec3& offset) { return extrude_vertices(m, selected, offset); }, true);
}

std::unique_ptr<ModalTool> TransformTool::duplicate(ToolContext& ctx) {
  const std::vector<int> faces = ctx.selection.faces(ctx.document.mesh());
  if (faces.empty()) {
    ctx.note("duplicate refused: select a face or more (all its corners)", true);
    return nullptr;
  }
  return move_after(
      ctx, "duplicate",
      [faces](const CovarianceMesh& m, const Vec3& offset) { return duplicate_faces(m, faces, offset); }, false);
}

void TransformTool::make_adjustable(const Vec3& moved, ToolContext& ctx) const {
  if (!ctx.adjustable || !make_) return;
  constexpr double kHuge = std::numeric_limits<double>::max();
  const double along = moved.dot(normal_);
  const MadeWithOffset make = make_;
  if (normal_ != Vec3::Zero() && (moved - along * normal_).norm() <= 1e-12 * std::max(1.0, moved.norm())) {
    const Vec3 normal = normal_;
    ctx.adjustable({operation_,
                    {{"offset along the normal", along, -kHuge, kHuge}},
                    before_,
                    [make, normal](const CovarianceMesh& before, const std::vector<double>& v) {
                      return make(before, v[0] * normal);
                    }});
    return;
  }
  ctx.adjustable({operation_,
                  {{"move x", moved.x(), -kHuge, kHuge},
                   {"move y", moved.y(), -kHuge, kHuge},
                   {"move z", moved.z(), -kHuge, kHuge}},
                  before_,
                  [make](const CovarianceMesh& before, const std::vector<double>& v) {
                    return make(before, Vec3(v[0], v[1], v[2]));
                  }});
}

void TransformTool::follow(glm::vec2 cursor, ToolContext& ctx) {
  snapped_.reset();
  if (!typed_.empty()) return;
  transform_->move_cursor(cursor, ctx.viewport);
  if (!ctx.snap.active(ctx.ctrl)) return;
  if (ctx.snap.target == SnapTarget::increment || transform_->kind() != TransformKind::grab) {
    transform_->snap_increment(ctx.snap.distance_step, ctx.snap.factor_step, ctx.snap.angle_step);
    return;
  }
  // Every vertex the transform reaches moves: none of them is a place to snap to.
  std::vector<int> moving;
  for (const ReachedVertex& r : reach_) moving.push_back(r.vertex);
  constexpr float kSnapRadius = 16.0f;  // window pixels
  snapped_ = find_snap_point(ctx.document.mesh(), ctx.viewport, cursor, ctx.snap.target, moving, kSnapRadius);
  if (snapped_) transform_->snap_to(snapped_->point);
}

void TransformTool::update(ToolContext& ctx) {
  const size_t clamped =
      apply_transform(ctx.document, *transform_, reach_, ctx.reach.mirror_axis, ctx.transform_gaussians);
  const bool snapping = ctx.snap.active(ctx.ctrl) && typed_.empty();
  status_ =
      transform_->describe() +
      (snapping ? snapped_ ? "  (snapped to " + snapped_->element + ")"
                           : std::string("  (snapping to ") + snap_target_name(ctx.snap.target) +
                                 (ctx.snap.target == SnapTarget::increment ? "s" : "") + ")"
                : "") +
      (reach_.size() > transform_->vertices().size() ? "  (" + std::to_string(reach_.size()) + " vertices)" : "") +
      (ctx.transform_gaussians ? "" : "  (positions only)") +
      (clamped ? "  (" + count_of(clamped, "Gaussian", "Gaussians") + " held at the flatness floor)" : "");
}

ToolResult TransformTool::handle(const InputEvent& e, ToolContext& ctx) {
  if (confirms(e) || cancels(e)) {
    const bool keep = confirms(e);
    end(keep, ctx);
    return keep ? ToolResult::confirmed : ToolResult::cancelled;
  }
  const bool key = e.type == InputEvent::Type::key_press;
  const bool ctrl_key = (e.type == InputEvent::Type::key_press || e.type == InputEvent::Type::key_release) &&
                        (e.key == GLFW_KEY_LEFT_CONTROL || e.key == GLFW_KEY_RIGHT_CONTROL);
  if (e.type == InputEvent::Type::move || ctrl_key) {  // Ctrl held or let go: snapping turns over
    follow(ctx.cursor, ctx);
  } else if (key && (e.key == GLFW_KEY_X || e.key == GLFW_KEY_Y || e.key == GLFW_KEY_Z)) {
    transform_->constrain_axis(e.key - GLFW_KEY_X, ctx.shift);
    follow(ctx.cursor, ctx);
  } else if (typed_.handle(e)) {
    transform_->set_typed(typed_.text(), typed_.value());
    if (!typed_.empty()) snapped_.reset();
  } else if (e.type == InputEvent::Type::scroll && ctx.reach.proportional && !folds_) {
    ctx.reach.radius *= std::pow(1.15, double(e.steps));
    const std::vector<Vec3> means = start_means(ctx.document);
    ctx.document.revert_edit();
    reach_ = edit_reach(means, transform_->vertices(), ctx.reach, ctx.hidden_vertices);
  } else if (key && e.key == GLFW_KEY_G && transform_->kind() == TransformKind::grab && !folds_) {
    ctx.document.cancel_edit();  // G G: the grab becomes a slide of the same selection
    ctx.next = SlideTool::start(ctx);
    return ToolResult::replaced;
  } else if (e.type != InputEvent::Type::release) {
    return e.type == InputEvent::Type::scroll ? ToolResult::passed_on : ToolResult::consumed;  // the wheel zooms
  }
  update(ctx);
  return ToolResult::consumed;
}

void TransformTool::draw_overlay(ImDrawList& draw, const ToolContext& ctx) const {
  if (!snapped_) return;
  const auto at = project_to_pixel(ctx.viewport.camera, ctx.viewport.width, ctx.viewport.height, snapped_->point);
  if (!at) return;
  const ImVec2 centre(at->x, at->y);
  draw.AddCircle(centre, 7.0f, IM_COL32(255, 255, 255, 255), 16, 2.0f);
  draw.AddCircleFilled(centre, 2.5f, IM_COL32(255, 255, 255, 255));
}

void TransformTool::end(bool keep, ToolContext& ctx) {
  if (!keep) {
    ctx.document.cancel_edit();
    ctx.report(folds_ ? "move cancelled (the " + operation_ + " stays; Ctrl+Z removes it)" : "transform cancelled",
               false);
    if (folds_) make_adjustable(Vec3::Zero(), ctx);
    return;
  }
  // A typed amount can carry a vertex past what a covariance mesh holds (a scale of 1e300): refused as
  // core's transform refuses it, nothing changed by the move.
  for (const ReachedVertex& r : reach_) {
    const CovarianceMesh& mesh = ctx.document.mesh();
    std::string why = position_problem(mesh.mean(size_t(r.vertex)));
    if (why.empty()) why = covariance_problem(mesh.covariance(size_t(r.vertex)));
    if (why.empty()) continue;
    ctx.document.cancel_edit();
    ctx.report("transform refused: vertex " + std::to_string(r.vertex) + " would have " +
                   (why.rfind("has ", 0) == 0 ? why.substr(4) : why) + "; nothing moved",
               true);
    if (folds_) make_adjustable(Vec3::Zero(), ctx);
    return;
  }
  if (folds_) {
    ctx.document.commit_edit_into_last_operation(ctx.selection.record());
    make_adjustable(transform_->map(0).translation, ctx);
    ctx.show_status(operation_ + ": " + operation_summary_, false);  // shown again, not printed again
    return;
  }
  const std::string described = transform_->describe();
  // The count of Gaussians held at the flatness floor stays in what is reported (the status line's last part).
  const size_t last_part = status_.rfind("  (");
  const std::string held =
      last_part != std::string::npos && status_.find("held at the flatness floor", last_part) != std::string::npos
          ? status_.substr(last_part)
          : "";
  const std::string done = described.substr(0, described.find("  (")) +
                           (snapped_ ? ", snapped to " + snapped_->element : "") +
                           (ctx.transform_gaussians ? "" : "  (positions only)") + held;
  // Vertices a mirror (negative determinant) carried: the parts they make up whole get their faces
  // reversed with them, as Blender does, so that the surface stays outward.
  std::vector<int> mirrored_vertices;
  std::vector<std::pair<int, Gaussian>> moved;
  for (const ReachedVertex& r : reach_) {
    AffineMap map = transform_->map(r.source, r.weight);
    if (r.mirrored) map = mirrored(map, ctx.reach.mirror_axis);
    if (map.linear.determinant() < 0) mirrored_vertices.push_back(r.vertex);
    const CovarianceMesh& mesh = ctx.document.mesh();
    moved.push_back({r.vertex, {mesh.mean(size_t(r.vertex)), mesh.covariance(size_t(r.vertex))}});
  }
  if (mirrored_vertices.empty()) {
    ctx.document.commit_edit();
    ctx.report(done, false);
    return;
  }
  // One undo step that replaces the mesh: the moved Gaussians and the reversed faces together.
  std::sort(mirrored_vertices.begin(), mirrored_vertices.end());
  ctx.document.cancel_edit();
  const std::vector<int> selected = ctx.selection.vertices();
  ctx.operate(
      done,
      [&](const CovarianceMesh& mesh) {
        MeshArrays a = arrays_of(mesh);
        for (const auto& [v, g] : moved) a.means[size_t(v)] = g.mean, a.covariances[size_t(v)] = g.covariance;
        reverse_parts_within(a, mirrored_vertices);
        return modelled(mesh, a, selected, "mirrored: the faces it moved whole reversed to stay outward");
      },
      nullptr);
}

}  // namespace gps
