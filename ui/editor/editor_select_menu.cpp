// The Select menu: the modes (1, 2, 3), all, none, invert, circle select, select similar, sharp
// edges, linked, grow, shrink and X-ray; each keeps the edges or faces held as the mode selects.
// Selecting with the pointer: ui/editing/pointer_selection.h, called from editor_pointer.cpp.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cctype>

#include "core/mesh/crease_by_angle.h"
#include "core/modelling/mesh_queries.h"
#include "core/modelling/operation_words.h"
#include "core/modelling/select_similar.h"
#include "core/support/error.h"
#include "ui/editor/editor_app.h"
#include "ui/editing/pointer_selection.h"
#include "ui/tools/circle_select_tool.h"

namespace gps {

void EditorApp::set_select_mode(SelectMode mode) {
  select_mode_ = mode;
  selection_.hold_for(mode, document_.mesh());
  set_status(select_mode_name(mode) + " select mode", false);
}

// Select similar's items for the selection mode, and its threshold: each adds the elements like a
// selected one (core/modelling/select_similar.h).
void EditorApp::draw_similar_items() {
  const CovarianceMesh& mesh = document_.mesh();
  const auto add = [&](Similarity similarity) {
    try {
      size_t found = 0;
      if (select_mode_ == SelectMode::edge) {
        const std::vector<EdgeEnds> edges = similar_edges(mesh, selection_.edges(mesh), similarity, similar_threshold_);
        selection_.hold_edges(mesh);
        selection_.select_edges(mesh, edges, true);
        found = edges.size();
      } else if (select_mode_ == SelectMode::face) {
        const std::vector<int> faces = similar_faces(mesh, selection_.faces(mesh), similarity, similar_threshold_);
        selection_.select_faces(mesh, faces, true);
        found = faces.size();
      } else {
        const std::vector<int> vertices = similar_vertices(mesh, selection_.vertices(), similarity);
        selection_.select(vertices, true);
        found = vertices.size();
      }
      set_status(std::string("similar ") + similarity_name(similarity) + ": " + std::to_string(found) + " selected",
                 false);
    } catch (const Error& e) {
      set_status(std::string("select similar: ") + e.what(), true);
    }
  };
  const std::vector<std::pair<const char*, Similarity>> items =
      select_mode_ == SelectMode::edge
          ? std::vector<std::pair<const char*, Similarity>>{{"Length", Similarity::edge_length},
                                                            {"Crease", Similarity::edge_crease}}
      : select_mode_ == SelectMode::face
          ? std::vector<std::pair<const char*, Similarity>>{{"Area", Similarity::face_area},
                                                            {"Sides", Similarity::face_sides},
                                                            {"Normal", Similarity::face_normal}}
          : std::vector<std::pair<const char*, Similarity>>{{"Number of edges", Similarity::vertex_edges}};
  for (const auto& [label, similarity] : items)
    if (ImGui::MenuItem(label)) add(similarity);
  ImGui::SetNextItemWidth(80.0f);
  ImGui::InputDouble("threshold", &similar_threshold_, 0.0, 0.0, "%.3g");
  similar_threshold_ = std::clamp(similar_threshold_, 0.0, 1.0);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("lengths and areas within this fraction, creases within this much, normals within this · 180°");
}

void EditorApp::select_sharp_edges() {
  const CovarianceMesh& mesh = document_.mesh();
  const std::vector<EdgeEnds> sharp = edges_sharper_than(mesh, sharp_edge_angle_);
  if (select_mode_ != SelectMode::edge) set_select_mode(SelectMode::edge);
  selection_.select_edges(mesh, sharp, true);  // added to the selection, as Blender does
  deselect_hidden();
  // Those selected: a hidden one is not.
  const std::vector<EdgeEnds> held = selection_.edges(mesh);
  const size_t selected = size_t(std::count_if(
      sharp.begin(), sharp.end(), [&](const EdgeEnds& e) { return std::binary_search(held.begin(), held.end(), e); }));
  set_status("select sharp edges: " + count_of(selected, "edge", "edges") + " folded by more than " +
                 short_number(sharp_edge_angle_) + "°" +
                 (selected < sharp.size() ? " (" + std::to_string(sharp.size() - selected) + " more hidden)" : ""),
             false);
}

void EditorApp::draw_sharp_edges_items() {
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6.0f);
  if (ImGui::InputDouble("angle (degrees)", &sharp_edge_angle_, 0.0, 0.0, "%.3g"))
    sharp_edge_angle_ = std::clamp(sharp_edge_angle_, 0.0, 180.0);
  if (ImGui::MenuItem("Select", "Ctrl+Shift+E")) select_sharp_edges();
}

void EditorApp::build_selection_commands() {
  const auto key = [](int k, bool ctrl = false, bool shift = false, bool alt = false) {
    return Shortcut{k, ctrl, shift, alt};
  };
  const auto always = std::function<bool()>();
  const auto has_selection = [this] { return !selection_.empty(); };
  // After a command that selects vertices: the edges or faces among them held, as the mode selects.
  const auto hold_for_mode = [this] { selection_.hold_for(select_mode_, document_.mesh()); };
  CommandTable& t = commands_;
  const std::pair<SelectMode, int> modes[] = {
      {SelectMode::vertex, GLFW_KEY_1}, {SelectMode::edge, GLFW_KEY_2}, {SelectMode::face, GLFW_KEY_3}};
  for (const auto& [mode, digit] : modes) {
    std::string label = select_mode_name(mode) + " select mode";
    label[0] = char(std::toupper(static_cast<unsigned char>(label[0])));
    t.add({"Select",
           label,
           {key(digit)},
           [this, m = mode] { set_select_mode(m); },
           always,
           [this, m = mode] { return select_mode_ == m; }});
  }
  t.add({"Select",
         "Select all",
         {key(GLFW_KEY_A), key(GLFW_KEY_A, true)},
         [this, hold_for_mode] {
           selection_.select_all(document_.mesh().n_vertices());
           hold_for_mode();
         },
         always,
         nullptr,
         nullptr,
         true});
  t.add({"Select", "Select none", {key(GLFW_KEY_A, false, false, true), key(GLFW_KEY_ESCAPE)}, [this] {
           selection_.clear();
         }});
  t.add({"Select", "Invert selection", {key(GLFW_KEY_I, true)}, [this] {
           if (select_mode_ == SelectMode::edge)
             selection_.invert_edges(document_.mesh());
           else if (select_mode_ == SelectMode::face)
             selection_.invert_faces(document_.mesh());
           else
             selection_.invert(document_.mesh().n_vertices());
         }});
  t.add(
      {"Select", "Circle select (C; drag to select, Shift+drag to deselect, wheel: radius)", {key(GLFW_KEY_C)}, [this] {
         start_tool([this](ToolContext& ctx) {
           return std::make_unique<CircleSelectTool>(ctx, select_mode_, select_through_);
         });
       }});
  t.add({"Select",
         "Select similar (Shift+G)",
         {key(GLFW_KEY_G, false, true)},
         [this] { popup_request_ = "Similar"; },
         [this] { return !selection_.empty(); },
         nullptr,
         [this] { draw_similar_items(); }});
  t.add({"Select",
         "Select sharp edges",
         {key(GLFW_KEY_E, true, true)},
         [this] { select_sharp_edges(); },
         always,
         nullptr,
         [this] { draw_sharp_edges_items(); }});
  t.add({"Select",
         "Select linked (under the cursor)",
         {key(GLFW_KEY_L)},
         [this, hold_for_mode] {
           const Viewport v = viewport();
           const std::vector<int> seeds = vertices_under(pointer_scene(v), input_.cursor);
           if (!seeds.empty()) selection_.select(linked_vertices(document_.mesh(), seeds), true);
           hold_for_mode();
         },
         always,
         nullptr,
         nullptr,
         true});
  t.add({"Select",
         "Select linked (from the selection)",
         {key(GLFW_KEY_L, true)},
         [this, hold_for_mode] {
           selection_.select(linked_vertices(document_.mesh(), selection_.vertices()), true);
           hold_for_mode();
         },
         has_selection});
  t.add({"Select",
         "Grow selection",
         {key(GLFW_KEY_KP_ADD, true)},
         [this, hold_for_mode] {
           selection_.select(grow_selection(document_.mesh(), selection_.vertices()), false);
           hold_for_mode();
         },
         has_selection});
  t.add({"Select",
         "Shrink selection",
         {key(GLFW_KEY_KP_SUBTRACT, true)},
         [this, hold_for_mode] {
           selection_.select(shrink_selection(document_.mesh(), selection_.vertices()), false);
           hold_for_mode();
         },
         has_selection});
  t.add({"Select",
         "Select through (X-ray)",
         {key(GLFW_KEY_Z, false, false, true)},
         [this] { select_through_ = !select_through_; },
         always,
         [this] { return select_through_; },
         nullptr,
         true});
}

}  // namespace gps
