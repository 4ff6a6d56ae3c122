// Spin as a modal tool.
#include "ui/tools/spin_tool.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/modelling/mesh_queries.h"
#include "core/modelling/operation_words.h"
#include "core/modelling/spin.h"
#include "core/support/error.h"
#include "ui/document/editor_document.h"
#include "ui/editing/selection.h"

namespace gps {

namespace {

constexpr int kMaxSpinSteps = 256;
const char* const kSpinAxisNames[] = {"x", "y", "z"};

}  // namespace

std::unique_ptr<ModalTool> SpinTool::start(ToolContext& ctx) {
  const CovarianceMesh& mesh = ctx.document.mesh();
  std::unique_ptr<SpinTool> tool(new SpinTool);
  try {
    tool->profile_ = chain_of_edges(ctx.selection.edges(mesh));
  } catch (const Error& e) {
    ctx.note(std::string("spin refused: ") + e.what(), true);
    return nullptr;
  }
  tool->base_ = std::make_shared<const CovarianceMesh>(mesh);
  tool->centre_ = ctx.cursor_point;
  const Camera& camera = ctx.viewport.camera;
  tool->view_axis_ = (to_vec(camera.eye_double()) - to_vec(camera.target)).normalized();
  tool->start_cursor_ = ctx.cursor;
  tool->update(ctx);
  return tool;
}

// The angle the pointer turned around the cursor's pixel since the tool began, counter-clockwise as
// seen (pixels run downward), about the axis toward the eye.
void SpinTool::follow(glm::vec2 cursor, const ToolContext& ctx) {
  const Viewport& v = ctx.viewport;
  const auto c = project_to_pixel(v.camera, v.width, v.height, centre_);
  if (!c) return;
  const glm::vec2 a = start_cursor_ - glm::vec2(*c), b = cursor - glm::vec2(*c);
  double turn = -(std::atan2(double(b.y), double(b.x)) - std::atan2(double(a.y), double(a.x))) * 180.0 / M_PI;
  if (turn > 180.0) turn -= 360.0;
  if (turn <= -180.0) turn += 360.0;
  const Vec3 axis = axis_ >= 0 ? Vec3(Vec3::Unit(axis_)) : view_axis_;
  degrees_ = axis.dot(view_axis_) < 0 ? -turn : turn;
}

void SpinTool::update(ToolContext& ctx) {
  const Vec3 axis = axis_ >= 0 ? Vec3(Vec3::Unit(axis_)) : view_axis_;
  char amount[160];
  std::snprintf(amount, sizeof amount, "spin: %s°%s about %s, %s", short_number(degrees_).c_str(),
                typed_.shown().c_str(), axis_ >= 0 ? kSpinAxisNames[axis_] : "the view axis",
                count_of(size_t(steps_), "step", "steps").c_str());
  const std::string keys =
      "  (turn the mouse around the 3D cursor or type degrees, wheel: steps, X Y Z: axis; "
      "click or Enter confirms, Esc cancels)";
  preview(
      ctx, degrees_ == 0.0, [&] { return spin(*base_, profile_, axis, centre_, degrees_, steps_); }, amount, keys);
}

ToolResult SpinTool::handle(const InputEvent& e, ToolContext& ctx) {
  if (cancelled_by(e, ctx, "spin", "angle 0")) return ToolResult::cancelled;
  if (confirms(e)) {  // one undo step: the spin shown
    if (!install_shown(ctx, "spin")) return ToolResult::confirmed;
    const std::vector<int> profile = profile_;
    const Vec3 axis = axis_ >= 0 ? Vec3(Vec3::Unit(axis_)) : view_axis_, centre = centre_;
    if (ctx.adjustable)
      ctx.adjustable({"spin",
                      {{"angle", degrees_, -360.0, 360.0}, {"steps", double(steps_), 1.0, double(kMaxSpinSteps), true}},
                      base_,
                      [profile, axis, centre](const CovarianceMesh& before, const std::vector<double>& v) {
                        return spin(before, profile, axis, centre, v[0], int(v[1]));
                      }});
    return ToolResult::confirmed;
  }
  const bool key = e.type == InputEvent::Type::key_press;
  if (e.type == InputEvent::Type::move) {
    if (!typed_.empty()) return ToolResult::consumed;
    follow(e.position, ctx);
  } else if (key && (e.key == GLFW_KEY_X || e.key == GLFW_KEY_Y || e.key == GLFW_KEY_Z)) {
    const int axis = e.key - GLFW_KEY_X;
    axis_ = axis_ == axis ? -1 : axis;  // the same axis again: the view axis
    if (typed_.empty()) follow(ctx.cursor, ctx);
  } else if (typed_.handle(e)) {
    const double typed = typed_.value();
    if (!std::isfinite(typed) && !typed_.empty()) return ToolResult::consumed;
    if (std::isfinite(typed))
      degrees_ = typed;
    else
      follow(ctx.cursor, ctx);  // nothing typed: the mouse's angle again
  } else if (e.type == InputEvent::Type::scroll) {
    steps_ = std::clamp(steps_ + wheel_.take(e.steps), 1, kMaxSpinSteps);
  } else {
    return ToolResult::consumed;
  }
  update(ctx);
  return ToolResult::consumed;
}

}  // namespace gps
