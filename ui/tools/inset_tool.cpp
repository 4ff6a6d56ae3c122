// The inset as a modal tool.
#include "ui/tools/inset_tool.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include "core/modelling/extrude.h"
#include "core/modelling/inset.h"
#include "core/modelling/mesh_queries.h"
#include "core/support/error.h"
#include "ui/document/editor_document.h"
#include "ui/editing/selection.h"

namespace gps {

namespace {

// The inset with its inner faces (its selection) moved `depth` along the region's area-weighted
// normal (Newell's sums), as Blender's Inset Faces' depth.
Modelled inset_with_depth(const CovarianceMesh& mesh, const std::vector<int>& faces, double thickness, double depth) {
  Modelled inset = inset_faces(mesh, faces, thickness);
  if (depth == 0.0) return inset;
  if (!std::isfinite(depth)) throw Error("inset depth must be finite");
  MeshArrays arrays = arrays_of(inset.mesh);
  Vec3 normal = Vec3::Zero();
  for (const int f : faces) normal += newell_normal(arrays, f);
  if (!(normal.norm() > 0)) throw Error("inset depth refused: the faces have no normal");
  normal.normalize();
  for (const int v : inset.selection) arrays.means[size_t(v)] += depth * normal;
  inset.mesh = build_mesh(arrays, inset.mesh);
  return inset;
}

}  // namespace

std::unique_ptr<ModalTool> InsetTool::start(ToolContext& ctx) {
  const CovarianceMesh& mesh = ctx.document.mesh();
  std::vector<int> faces = ctx.selection.faces(mesh);
  if (faces.empty()) {
    ctx.note("inset refused: select the corners of one face or more", true);
    return nullptr;
  }
  std::unique_ptr<InsetTool> tool(new InsetTool);
  tool->base_ = std::make_shared<const CovarianceMesh>(mesh);
  tool->faces_ = std::move(faces);
  tool->selection_before_ = ctx.selection.record();
  tool->centre_ = centre_of_vertices(mesh, ctx.selection.vertices());
  tool->start_cursor_ = ctx.cursor;
  tool->status_ = "inset: move toward the faces' centre (or type the thickness), click or Enter confirms, Esc cancels";
  return tool;
}

void InsetTool::update(double thickness, ToolContext& ctx) {
  if (!(thickness > 0)) return;
  try {
    const Modelled inset = inset_faces(*base_, faces_, thickness);
    if (!applied_) {
      ctx.install(inset, nullptr);
      applied_ = true;
      ctx.document.begin_edit();
    } else if (!ctx.document.set_gaussians(inset.mesh)) {
      return;
    }
    summary_ = inset.summary;
    thickness_ = thickness;
    char text[128];
    std::snprintf(text, sizeof text, "inset: thickness %.4f%s (click or Enter confirms, Esc cancels)", thickness,
                  typed_.shown().c_str());
    status_ = text;
    error_ = false;
  } catch (const Error& e) {
    status_ = std::string("inset: ") + e.what();
    error_ = true;
  }
}

void InsetTool::follow(glm::vec2 cursor, ToolContext& ctx) {
  const Viewport& v = ctx.viewport;
  const auto c = project_to_pixel(v.camera, v.width, v.height, centre_);
  if (!c) return;
  const glm::vec2 centre(*c);
  const double pixels = double(glm::length(start_cursor_ - centre) - glm::length(cursor - centre));
  update(pixels * world_per_pixel(v.camera, v.height, centre_), ctx);
}

void InsetTool::end(bool keep, ToolContext& ctx) {
  if (!applied_) {  // a thickness core refused says why
    const std::string why =
        error_ ? status_ + ": nothing done" : "inset: nothing done (move toward the centre or type a thickness)";
    ctx.report(keep ? why : "inset cancelled", keep && error_);
  } else if (keep) {
    ctx.document.commit_edit_into_last_operation(ctx.selection.record());
    ctx.note("inset: " + summary_, false);
    if (ctx.adjustable) {
      const std::vector<int> faces = faces_;
      constexpr double kHuge = std::numeric_limits<double>::max();
      ctx.adjustable({"inset",
                      {{"thickness", thickness_, 0.0, kHuge}, {"depth", 0.0, -kHuge, kHuge}},
                      base_,
                      [faces](const CovarianceMesh& before, const std::vector<double>& v) {
                        return inset_with_depth(before, faces, v[0], v[1]);
                      }});
    }
  } else {
    ctx.document.cancel_edit();
    ctx.document.discard_last_operation();
    ctx.rebuild(selection_before_);
    ctx.report("inset cancelled", false);
  }
}

ToolResult InsetTool::handle(const InputEvent& e, ToolContext& ctx) {
  if (confirms(e) || cancels(e)) {
    const bool keep = confirms(e);
    end(keep, ctx);
    return keep ? ToolResult::confirmed : ToolResult::cancelled;
  }
  if (e.type == InputEvent::Type::move && typed_.empty()) {
    follow(e.position, ctx);
  } else if (typed_.handle(e)) {
    if (std::isfinite(typed_.value())) update(typed_.value(), ctx);
  } else if (e.type == InputEvent::Type::scroll) {
    return ToolResult::passed_on;
  }
  return ToolResult::consumed;
}

}  // namespace gps
