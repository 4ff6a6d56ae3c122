// The editor as a modeller: the Mesh menu's operations, each one undo step that replaces the mesh,
// with its summary or refusal in the status bar and the Inspector. The modal tools that follow the
// mouse are in ui/tools/, started here and run by editor_modal_tools.cpp.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <utility>

#include "core/edit/covariance_edit.h"
#include "core/support/error.h"
#include "core/mesh/mesh_connectivity.h"
#include "core/modelling/bridge.h"
#include "core/modelling/delete_elements.h"
#include "core/modelling/edge_operations.h"
#include "core/modelling/fill.h"
#include "core/modelling/grid_fill.h"
#include "core/modelling/merge_vertices.h"
#include "core/modelling/mesh_queries.h"
#include "core/modelling/primitives.h"
#include "core/modelling/split_faces.h"
#include "core/modelling/subdivide_mesh.h"
#include "ui/editing/crease_tool.h"
#include "ui/editor/editor_app.h"
#include "ui/overlays/cursor_overlay.h"
#include "ui/tools/bevel_tool.h"
#include "ui/tools/bisect_tool.h"
#include "ui/tools/brush_tool.h"
#include "ui/tools/inset_tool.h"
#include "ui/tools/knife_tool.h"
#include "ui/tools/loop_cut_tool.h"
#include "ui/tools/sharpness_tool.h"
#include "ui/tools/spin_tool.h"
#include "ui/tools/transform_tool.h"

namespace gps {

namespace {

// The two selected vertices as an edge, for split and flip.
std::array<int, 2> selected_edge(const std::vector<int>& selected) {
  if (selected.size() != 2) throw Error("select the two vertices of one edge");
  return {selected[0], selected[1]};
}

}  // namespace

void EditorApp::build_modelling_commands() {
  const auto key = [](int k, bool ctrl = false, bool shift = false, bool alt = false) {
    return Shortcut{k, ctrl, shift, alt};
  };
  const auto always = std::function<bool()>();
  const auto selected = [this] { return !selection_.empty(); };
  CommandTable& t = commands_;
  const auto op = [this](const std::string& name, std::function<Modelled(const CovarianceMesh&)> run) {
    return [this, name, run] { run_operation(name, run); };
  };
  const auto transform = [this](TransformKind kind) {
    return [this, kind] {
      if (selection_.empty()) return;
      start_tool([&](ToolContext& ctx) { return std::make_unique<TransformTool>(kind, transform_pivot_, ctx); });
    };
  };
  t.add({"Mesh",
         "Grab (G; then X Y Z, digits, Enter; G again slides)",
         {key(GLFW_KEY_G)},
         transform(TransformKind::grab),
         selected});
  t.add({"Mesh", "Scale (S)", {key(GLFW_KEY_S)}, transform(TransformKind::scale), selected});
  t.add({"Mesh", "Rotate (R)", {key(GLFW_KEY_R)}, transform(TransformKind::rotate), selected});
  const auto pivot = [this](TransformPivot p) {
    return [this, p] {
      transform_pivot_ = p;
      set_status(std::string("pivot: ") + pivot_name(p), false);
    };
  };
  const auto pivot_is = [this](TransformPivot p) { return [this, p] { return transform_pivot_ == p; }; };
  t.add({"Mesh",
         "Pivot: median point",
         {key(GLFW_KEY_COMMA, true)},
         pivot(TransformPivot::median),
         always,
         pivot_is(TransformPivot::median)});
  t.add({"Mesh",
         "Pivot: active vertex",
         {key(GLFW_KEY_PERIOD, false, false, true)},
         pivot(TransformPivot::active),
         always,
         pivot_is(TransformPivot::active)});
  t.add({"Mesh",
         "Pivot: individual origins",
         {key(GLFW_KEY_PERIOD, true)},
         pivot(TransformPivot::individual),
         always,
         pivot_is(TransformPivot::individual)});
  t.add({"Mesh", "Pivot: 3D cursor", {}, pivot(TransformPivot::cursor), always, pivot_is(TransformPivot::cursor)});
  t.add({"", "Pivot: the next one", {key(GLFW_KEY_PERIOD)}, [this] {
           transform_pivot_ = TransformPivot((int(transform_pivot_) + 1) % kTransformPivots);
           set_status(std::string("pivot: ") + pivot_name(transform_pivot_), false);
         }});
  t.add({"Mesh",
         "Extrude",
         {key(GLFW_KEY_E)},
         [this] { start_tool(TransformTool::extrude); },
         selected,
         nullptr,
         nullptr,
         true});
  t.add({"Mesh",
         "Sharpen brush (Shift+P; paint: flatten the Gaussians along the normal, Shift: soften)",
         {key(GLFW_KEY_P, false, true)},
         [this] { start_tool([](ToolContext& ctx) { return BrushTool::start(ctx, BrushKind::sharpen); }); },
         [this] { return document_.mesh().n_vertices() > 0; }});
  t.add({"Mesh",
         "Soften brush (Alt+P; paint: make the Gaussians round, Shift: sharpen)",
         {key(GLFW_KEY_P, false, false, true)},
         [this] { start_tool([](ToolContext& ctx) { return BrushTool::start(ctx, BrushKind::soften); }); },
         [this] { return document_.mesh().n_vertices() > 0; }});
  t.add({"Mesh",
         "Bisect (Alt+K; drag a line: the cut is the plane seen along it)",
         {key(GLFW_KEY_K, false, false, true)},
         [this] { start_tool([](ToolContext& ctx) { return std::make_unique<BisectTool>(ctx); }); },
         [this] { return document_.mesh().n_faces() > 0; }});
  t.add({"Mesh",
         "Duplicate (Shift+D; then move)",
         {key(GLFW_KEY_D, false, true)},
         [this] { start_tool(TransformTool::duplicate); },
         selected});
  const auto has_edge = [this] { return !selection_.edges(document_.mesh()).empty(); };
  t.add({"Mesh",
         "Crease (Shift+E; drag or type 0-10, 10 = ∞)",
         {key(GLFW_KEY_E, false, true)},
         [this] { start_tool([](ToolContext& ctx) { return SharpnessTool::start(ctx, false); }); },
         has_edge});
  t.add({"Mesh",
         "Corner sharpness (Ctrl+Shift+V)",
         {key(GLFW_KEY_V, true, true)},
         [this] {
           if (!selection_.empty()) start_tool([](ToolContext& ctx) { return SharpnessTool::start(ctx, true); });
         },
         selected});
  t.add({"Mesh", "Loop cut (then wheel: cuts)", {key(GLFW_KEY_R, true)}, [this] {
           start_tool([](ToolContext& ctx) { return std::make_unique<LoopCutTool>(ctx); });
         }});
  t.add({"Mesh", "Knife (K; click points, Enter or Space cuts, Backspace takes one back)", {key(GLFW_KEY_K)}, [this] {
           start_tool([](ToolContext& ctx) { return std::make_unique<KnifeTool>(ctx); });
         }});
  t.add({"Mesh", "Inset faces", {key(GLFW_KEY_I)}, [this] { start_tool(InsetTool::start); }, selected});
  t.add({"Mesh",
         "Spin around the 3D cursor (Alt+R; mouse or typed degrees, wheel: steps)",
         {key(GLFW_KEY_R, false, false, true)},
         [this] { start_tool(SpinTool::start); },
         selected});
  t.add({"Mesh",
         "Bevel edges (Ctrl+B; then wheel: segments, P: profile)",
         {key(GLFW_KEY_B, true)},
         [this] { start_tool([](ToolContext& ctx) { return BevelTool::start(ctx, false); }); },
         selected});
  t.add({"Mesh",
         "Bevel vertices (Ctrl+Shift+B)",
         {key(GLFW_KEY_B, true, true)},
         [this] { start_tool([](ToolContext& ctx) { return BevelTool::start(ctx, true); }); },
         selected});
  t.add({"Mesh",
         "Fill",
         {key(GLFW_KEY_F)},
         op("fill", [this](const CovarianceMesh& m) { return fill_selected(m, selection_.vertices()); }),
         selected});
  // Grid fill, its span and offset adjustable afterwards (F9) as in Blender's panel of the operation.
  const auto grid_fill_selection = [this] {
    const std::vector<int> loop = selection_.vertices();
    const auto before = std::make_shared<const CovarianceMesh>(document_.mesh());
    if (!run_operation("grid fill", [&](const CovarianceMesh& m) { return grid_fill_selected(m, loop); })) return;
    const double n = double(loop.size());
    adjustable_ =
        AdjustableOperation{"grid fill",
                            {{"span (0: calculated)", 0.0, 0.0, n / 2 - 1, true}, {"offset", 0.0, 1 - n, n - 1, true}},
                            before,
                            [loop](const CovarianceMesh& m, const std::vector<double>& v) {
                              return grid_fill_selected(m, loop, int(v[0]), int(v[1]));
                            },
                            document_.last_step()};
  };
  t.add({"Mesh",
         "Grid fill (Ctrl+F; a whole boundary loop of an even count; F9: span, offset)",
         {key(GLFW_KEY_F, true)},
         grid_fill_selection,
         selected});
  // Blender's Y splits the faces off in the object, P separates them into a new one: with one mesh
  // to a document both detach the faces as a part of their own (File > Save selection as... writes it).
  const auto split = [this, op](const std::string& name) {
    return op(name, [this](const CovarianceMesh& m) { return split_faces(m, selection_.faces(m)); });
  };
  t.add({"Mesh",
         "Split (Y; the selected faces become a part of their own)",
         {key(GLFW_KEY_Y)},
         split("split"),
         selected});
  t.add({"Mesh", "Separate selection (P; as Split)", {key(GLFW_KEY_P)}, split("separate"), selected});
  t.add({"Mesh",
         "Bridge edge loops",
         {key(GLFW_KEY_E, true)},
         op("bridge",
            [this](const CovarianceMesh& m) {
              // Faces held: they go and the loops they leave are bridged (Blender's); else the vertices' loops.
              return selection_.holds_faces() ? bridge_faces(m, selection_.faces(m))
                                              : bridge_selected(m, selection_.vertices());
            }),
         selected});
  t.add({"Mesh",
         "Subdivide (the selected faces; all when none)",
         {key(GLFW_KEY_W)},
         op("subdivide", [this](const CovarianceMesh& m) {
           const std::vector<int> faces = selection_.faces(m);
           return faces.empty() ? subdivide_all(m) : subdivide_faces(m, faces);
         })});
  t.add({"Mesh",
         "Split edge",
         {},
         op("split edge",
            [this](const CovarianceMesh& m) {
              const auto e = selected_edge(selection_.vertices());
              return split_edge(m, e[0], e[1]);
            }),
         selected});
  t.add({"Mesh",
         "Flip edge",
         {},
         op("flip edge",
            [this](const CovarianceMesh& m) {
              const auto e = selected_edge(selection_.vertices());
              return flip_edge(m, e[0], e[1]);
            }),
         selected});
  t.add({"Mesh",
         "Delete",
         {key(GLFW_KEY_X), key(GLFW_KEY_DELETE)},
         [this] { popup_request_ = "Delete"; },
         selected,
         nullptr,
         [this] { draw_delete_items(); },
         true});
  t.add({"Mesh",
         "Merge",
         {key(GLFW_KEY_M)},
         [this] { popup_request_ = "Merge"; },
         selected,
         nullptr,
         [this] { draw_merge_items(); }});
  t.add({"Mesh",
         "Add",
         {key(GLFW_KEY_A, false, true)},
         [this] { popup_request_ = "Add"; },
         always,
         nullptr,
         [this] { draw_add_items(); }});
}

void EditorApp::draw_delete_items() {
  const std::vector<int>& s = selection_.vertices();
  const std::vector<EdgeEnds> edges = selection_.edges(document_.mesh());
  const std::vector<int> faces = selection_.faces(document_.mesh());
  if (ImGui::MenuItem("Vertices"))
    run_operation("delete vertices", [&s](const CovarianceMesh& m) { return delete_vertices(m, s); });
  if (ImGui::MenuItem("Edges"))
    run_operation("delete edges", [&edges](const CovarianceMesh& m) { return delete_edges(m, edges); });
  if (ImGui::MenuItem("Faces"))
    run_operation("delete faces", [&faces](const CovarianceMesh& m) { return delete_faces(m, faces); });
  ImGui::Separator();
  if (ImGui::MenuItem("Dissolve vertices"))
    run_operation("dissolve vertices", [&s](const CovarianceMesh& m) { return dissolve_vertices(m, s); });
  if (ImGui::MenuItem("Dissolve edges"))
    run_operation("dissolve edges", [&edges](const CovarianceMesh& m) { return dissolve_edges(m, edges); });
}

void EditorApp::draw_merge_items() {
  const std::vector<int>& s = selection_.vertices();
  const std::pair<const char*, MergePoint> points[] = {
      {"At center", MergePoint::center}, {"At first", MergePoint::first}, {"At last", MergePoint::last}};
  for (const auto& [label, point] : points)
    if (ImGui::MenuItem(label))
      run_operation("merge", [&s, point = point](const CovarianceMesh& m) { return merge_vertices(m, s, point); });
  ImGui::Separator();
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6.0f);
  ImGui::InputDouble("distance (of the diagonal)", &merge_distance_, 0.0, 0.0, "%.3g");
  if (ImGui::MenuItem("By distance"))
    run_operation("merge by distance", [&s, fraction = merge_distance_](const CovarianceMesh& m) {
      return merge_by_distance(m, s, fraction);
    });
}

void EditorApp::draw_add_items() {
  for (const std::string& name : primitive_names()) {
    if (!ImGui::MenuItem(name.c_str())) continue;
    PrimitivePlacement at = primitive_placement(document_.mesh(), selection_.vertices());
    if (cursor_.placed) at.center = cursor_.point;
    run_operation("add " + name, [&](const CovarianceMesh& m) {
      return add_primitive(m, *primitive_named(name), at.center, at.size);
    });
  }
}

void EditorApp::apply_sharpness(bool corners, double sharpness) {
  const Selection before = selection_;
  const bool done = run_operation(corners ? "corner" : "crease", [&](const CovarianceMesh& m) {
    return sharpened_selection(m, before, corners, sharpness, reach_options_);
  });
  if (done) selection_ = before;  // the selection as it was (set_crease selects the edges' ends)
}

// The popup menus of X, M and Shift+A, and what the modal tool draws (a loop cut's ring).

void EditorApp::draw_modelling_overlay() {
  if (!popup_request_.empty()) {
    ImGui::OpenPopup(popup_request_.c_str());
    popup_request_.clear();
  }
  if (ImGui::BeginPopup("Delete")) {
    draw_delete_items();
    ImGui::EndPopup();
  }
  if (ImGui::BeginPopup("Merge")) {
    draw_merge_items();
    ImGui::EndPopup();
  }
  if (ImGui::BeginPopup("Add")) {
    draw_add_items();
    ImGui::EndPopup();
  }
  if (ImGui::BeginPopup("Similar")) {
    draw_similar_items();
    ImGui::EndPopup();
  }
  if (cursor_.placed) draw_cursor_overlay(*ImGui::GetBackgroundDrawList(), viewport(), cursor_.point);
  if (tool_) tool_->draw_overlay(*ImGui::GetBackgroundDrawList(), tool_context());
}

}  // namespace gps
