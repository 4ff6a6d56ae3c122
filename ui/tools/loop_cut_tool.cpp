// The loop cut as a modal tool, and the edge under the cursor it starts from.
#include "ui/tools/loop_cut_tool.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/support/error.h"
#include "ui/document/editor_document.h"
#include "ui/editing/selection.h"

namespace gps {

namespace {

constexpr float kEdgePickPixels = 40.0f;  // how near the cursor an edge must be for a loop cut
constexpr int kMaxLoopCuts = 64;          // what the wheel reaches
constexpr double kMaxLoopSlide = 0.95;    // short of the ring's edges' ends

// Whether face f of `mesh` faces the camera (Newell's normal of its means against the view); no face (−1) does not.
bool faces_the_camera(const CovarianceMesh& mesh, const Viewport& view, int f) {
  if (f < 0) return false;
  Vec3 normal = Vec3::Zero(), centre = Vec3::Zero();
  std::vector<Vec3> corners;
  for (const int v : mesh.face(size_t(f))) corners.push_back(mesh.mean(size_t(v)));
  for (size_t i = 0; i < corners.size(); ++i) {
    normal += corners[i].cross(corners[(i + 1) % corners.size()]);
    centre += corners[i] / double(corners.size());
  }
  const Vec3 eye = to_vec(view.camera.eye_double()), forward = to_vec(view.camera.target) - eye;
  return view.camera.orthographic ? normal.dot(forward) < 0 : normal.dot(eye - centre) > 0;
}

}  // namespace

std::optional<std::array<int, 2>> edge_under(const CovarianceMesh& mesh, const Viewport& v, glm::vec2 cursor) {
  std::optional<std::array<int, 2>> best;
  float nearest = kEdgePickPixels;
  const std::vector<int>& sides = mesh.connectivity().edge_faces;
  for (size_t e = 0; e < mesh.n_edges(); ++e) {
    if (!faces_the_camera(mesh, v, sides[2 * e]) && !faces_the_camera(mesh, v, sides[2 * e + 1])) continue;
    const auto [a, b] = mesh.edge(e);
    const auto pa = visible_pixel(v.camera, v.width, v.height, mesh.mean(size_t(a)));
    const auto pb = visible_pixel(v.camera, v.width, v.height, mesh.mean(size_t(b)));
    if (!pa || !pb) continue;
    const glm::vec2 p(pa->x, pa->y), q(pb->x, pb->y), d = q - p;
    const float t = glm::dot(d, d) > 0 ? std::clamp(glm::dot(cursor - p, d) / glm::dot(d, d), 0.0f, 1.0f) : 0.0f;
    const float distance = glm::length(cursor - (p + t * d));
    if (distance < nearest) nearest = distance, best = std::array<int, 2>{a, b};
  }
  return best;
}

LoopCutTool::LoopCutTool(ToolContext& ctx) {
  hover(ctx.cursor, ctx);
  status_ = "loop cut: point at an edge; the wheel sets the cuts, click to cut, Esc cancels";
}

void LoopCutTool::hover(glm::vec2 cursor, const ToolContext& ctx) {
  ring_ = {};
  const auto edge = edge_under(ctx.document.mesh(), ctx.viewport, cursor);
  if (!edge) return;
  try {
    ring_ = edge_ring(ctx.document.mesh(), (*edge)[0], (*edge)[1]);
  } catch (const Error&) {
  }
}

ToolResult LoopCutTool::cut(ToolContext& ctx) {
  if (ring_.edges.empty()) return ToolResult::consumed;
  const auto [a, b] = ring_.edges.front();
  base_ = std::make_shared<const CovarianceMesh>(ctx.document.mesh());
  try {
    const Modelled result = loop_cut(*base_, a, b, cuts_);
    ctx.install(result, nullptr);
    summary_ = result.summary;
  } catch (const Error& e) {  // refused: nothing changed
    ctx.note(std::string("loop cut refused: ") + e.what(), true);
    return ToolResult::cancelled;
  }
  sliding_ = true;
  typed_ = {};  // the cuts' number was typed; the slide's may be
  start_cursor_ = ctx.cursor;
  ctx.document.begin_edit();
  status_ = "loop cut: move to slide, click or Enter to confirm, Esc keeps it in the middle";
  return ToolResult::consumed;
}

void LoopCutTool::slide(glm::vec2 cursor, ToolContext& ctx) {
  const auto [a, b] = ring_.edges.front();
  const Viewport& v = ctx.viewport;
  const auto pa = project_to_pixel(v.camera, v.width, v.height, base_->mean(size_t(a)));
  const auto pb = project_to_pixel(v.camera, v.width, v.height, base_->mean(size_t(b)));
  if (!pa || !pb) return;
  const glm::vec2 d = glm::vec2(*pb) - glm::vec2(*pa);
  if (glm::dot(d, d) < 1.0f) return;
  slide_to(
      std::clamp(2.0 * double(glm::dot(cursor - start_cursor_, d) / glm::dot(d, d)), -kMaxLoopSlide, kMaxLoopSlide),
      ctx);
}

void LoopCutTool::slide_to(double slide, ToolContext& ctx) {
  const auto [a, b] = ring_.edges.front();
  try {
    const Modelled slid = loop_cut(*base_, a, b, cuts_, slide);
    if (!ctx.document.set_gaussians(slid.mesh)) return;
    slide_ = slide;
    char text[96];
    std::snprintf(text, sizeof text, "loop cut: slide %.3f%s (click or Enter confirms, Esc keeps it in the middle)",
                  slide, typed_.shown().c_str());
    status_ = text;
  } catch (const Error&) {
  }
}

void LoopCutTool::end(bool keep, ToolContext& ctx) {
  if (!sliding_) {
    ctx.report("loop cut cancelled", false);
    return;
  }
  if (keep) {
    ctx.document.commit_edit_into_last_operation(ctx.selection.record());
  } else {
    ctx.document.cancel_edit();
    slide_ = 0.0;
  }
  ctx.note("loop cut: " + summary_, false);
  if (ctx.adjustable) {
    const int a = ring_.edges.front()[0], b = ring_.edges.front()[1];
    ctx.adjustable({"loop cut",
                    {{"number of cuts", double(cuts_), 1.0, double(kMaxLoopCuts), true},
                     {"slide", slide_, -kMaxLoopSlide, kMaxLoopSlide}},
                    base_,
                    [a, b](const CovarianceMesh& before, const std::vector<double>& v) {
                      return loop_cut(before, a, b, int(v[0]), v[1]);
                    }});
  }
}

ToolResult LoopCutTool::handle(const InputEvent& e, ToolContext& ctx) {
  if (cancels(e)) {
    end(false, ctx);
    return ToolResult::cancelled;
  }
  if (confirms(e)) {
    if (!sliding_) return cut(ctx);
    end(true, ctx);
    return ToolResult::confirmed;
  }
  if (e.type == InputEvent::Type::move) {
    if (sliding_ && typed_.empty())
      slide(e.position, ctx);
    else if (!sliding_)
      hover(e.position, ctx);
  } else if (typed_.handle(e)) {
    typed(ctx);
  } else if (e.type == InputEvent::Type::scroll) {
    if (sliding_) return ToolResult::passed_on;
    cuts_ = std::clamp(cuts_ + wheel_.take(e.steps), 1, kMaxLoopCuts);
    status_ = "loop cut: " + std::to_string(cuts_) + " cuts (wheel), click to cut, Esc cancels";
  }
  return ToolResult::consumed;
}

void LoopCutTool::typed(ToolContext& ctx) {
  const double value = typed_.value();
  if (sliding_) {
    if (std::isfinite(value))
      slide_to(std::clamp(value, -kMaxLoopSlide, kMaxLoopSlide), ctx);
    else if (typed_.empty())
      slide(ctx.cursor, ctx);  // nothing typed: the mouse's slide again
    return;
  }
  // A whole number of cuts; anything else waits for more typing.
  if (std::isfinite(value) && value >= 1 && value == std::floor(value))
    cuts_ = int(std::min<double>(value, kMaxLoopCuts));
  status_ = "loop cut: " + std::to_string(cuts_) + " cuts" + typed_.shown() + ", click to cut, Esc cancels";
}

// The ring's cuts as lines across its edges, before the cut.
void LoopCutTool::draw_overlay(ImDrawList& draw, const ToolContext& ctx) const {
  if (sliding_ || ring_.edges.empty()) return;
  const Viewport& v = ctx.viewport;
  const CovarianceMesh& mesh = ctx.document.mesh();
  for (int k = 1; k <= cuts_; ++k) {
    const double t = double(k) / double(cuts_ + 1);
    std::vector<ImVec2> points;
    for (const auto& [a, b] : ring_.edges) {
      const Vec3 p = (1.0 - t) * mesh.mean(size_t(a)) + t * mesh.mean(size_t(b));
      if (const auto q = project_to_pixel(v.camera, v.width, v.height, p)) points.emplace_back(q->x, q->y);
    }
    draw.AddPolyline(points.data(), int(points.size()), IM_COL32(255, 210, 60, 255),
                     ring_.closed ? ImDrawFlags_Closed : ImDrawFlags_None, 2.0f);
  }
}

}  // namespace gps
