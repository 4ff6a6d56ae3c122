// The editor's pointer: clicks and boxes select, drags orbit and pan, the wheel zooms, and a drag
// on the gizmo edits the selection (with its proportional and mirrored reach) as one undo step.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cmath>

#include "core/modelling/mesh_queries.h"
#include "ui/input/camera_control.h"
#include "ui/overlays/crease_overlay.h"
#include "ui/editor/editor_app.h"
#include "ui/overlays/ellipsoid_scope.h"
#include "ui/overlays/handle_overlay.h"
#include "ui/editing/pointer_selection.h"
#include "ui/tools/handle_drag_tool.h"
#include "view/picking.h"

namespace gps {

namespace {
constexpr float kPickRadius = 8.0f;    // window pixels
constexpr float kBoxThreshold = 4.0f;  // pixels a left press moves before it becomes a box
}  // namespace

PointerScene EditorApp::pointer_scene(const Viewport& v) const {
  return {v,
          document_.mesh(),
          select_mode_,
          hidden_.vertex_mask(),
          hidden_.edge_mask(),
          hidden_.face_mask(),
          select_through_};
}

Viewport EditorApp::viewport() const {
  Viewport v;
  v.camera = camera_;
  glfwGetWindowSize(window_.window(), &v.width, &v.height);
  v.width = std::max(1, v.width);
  v.height = std::max(1, v.height);
  return v;
}

// One gizmo for the selection, with the active vertex's axes, on that vertex or at the selected
// vertices' centroid (View panel); its change applies to every selected vertex.
Vec3 EditorApp::gizmo_pivot() const {
  const CovarianceMesh& mesh = document_.mesh();
  const std::vector<int>& selected = selection_.vertices();
  if (view_.pivot == 0 || selected.size() < 2) return mesh.mean(size_t(selection_.active()));
  Vec3 sum = Vec3::Zero();
  for (const int v : selected) sum += mesh.mean(size_t(v));
  return sum / double(selected.size());
}

std::optional<HandleFrame> EditorApp::gizmo_frame(const Viewport& v) const {
  if (selection_.empty()) return std::nullopt;
  const Mat3& covariance = document_.mesh().covariance(size_t(selection_.active()));
  return handle_frame(gizmo_pivot(), ellipsoid_axes(covariance), view_.draw.sigma_scale, v);
}

int EditorApp::pick(glm::vec2 pixel) const {
  const Viewport v = viewport();
  const int vertex = pick_visible_vertex(pointer_scene(v), pixel, kPickRadius);
  if (vertex >= 0 || !view_.draw.ellipsoids) return vertex;
  const bool all = hidden_.elements().empty() &&
                   all_ellipsoids(EllipsoidScope(view_.ellipsoid_scope), document_.mesh().n_vertices());
  return pick_ellipsoid(v.camera, v.width, v.height, pixel, document_.mesh(), view_.draw.sigma_scale,
                        all ? nullptr : &shown_ellipsoids_);
}

// Whether a click at `pixel` on the gizmo's axis end `handle` means an unselected vertex that lies as
// near the click as the end (a neighbour the end sits on): the click then selects it.
bool EditorApp::vertex_before_handle(glm::vec2 pixel, const HandleFrame& gizmo, const Handle& handle) const {
  const Viewport v = viewport();
  const int vertex = pick_visible_vertex(pointer_scene(v), pixel, kPickRadius);
  if (vertex < 0 || selection_.contains(vertex)) return false;
  const auto at_vertex = visible_pixel(v.camera, v.width, v.height, document_.mesh().mean(size_t(vertex)));
  const auto at_end = visible_pixel(v.camera, v.width, v.height, gizmo.end(handle.axis, handle.side));
  return at_vertex &&
         (!at_end || glm::length(glm::vec2(*at_vertex) - pixel) <= glm::length(glm::vec2(*at_end) - pixel));
}

void EditorApp::handle_event(const InputEvent& e) {
  const ImGuiIO& io = ImGui::GetIO();
  deselect_hidden();  // what a tool or a menu selected last, before anything acts on the selection
  // The modal tool running takes the events first (editor_modal_tools.cpp).
  if (modal_event(e)) return;
  if (mesh_jobs_.is_open() || repair_prompt_.is_open()) {  // their keys are Dear ImGui's; a mesh dropped now waits
    if (e.type == InputEvent::Type::drop) set_status("close the dialog first", true);
    if (e.type == InputEvent::Type::key_press || e.type == InputEvent::Type::drop) return;
  }
  switch (e.type) {
    case InputEvent::Type::press:
      if (!io.WantCaptureMouse && !prompt_unsaved_) press(e);
      break;
    case InputEvent::Type::release:
      follow_cursor();  // the motion that came in the release's frame, before the release ends the drag
      release(e);
      break;
    case InputEvent::Type::scroll:
      if (!io.WantCaptureMouse) {
        const Viewport v = viewport();
        std::optional<glm::dvec3> anchor;
        if (const auto hit = surface_at(e.position)) anchor = glm::dvec3(hit->x(), hit->y(), hit->z());
        zoom_to_cursor(camera_, e.steps, v.width, v.height, e.position, anchor);
      }
      break;
    case InputEvent::Type::key_press:
      if (!io.WantCaptureKeyboard && !browser_.is_open())
        commands_.handle_key(e.key, input_.ctrl(), input_.shift(), input_.alt());
      break;
    case InputEvent::Type::drop:
      if (!e.paths.empty()) request({Action::Kind::open_file, e.paths.front()});
      break;
    case InputEvent::Type::move:
    case InputEvent::Type::key_release:
    case InputEvent::Type::text:
      break;
  }
}

void EditorApp::press(const InputEvent& e) {
  if (mode_ != Mode::none) return;
  mode_button_ = e.button;
  press_pixel_ = last_cursor_ = e.position;
  alt_press_ = e.button == 0 && input_.alt();
  if (e.button == 0 && !input_.alt()) {
    const Viewport v = viewport();
    const auto gizmo = gizmo_frame(v);
    auto handle = gizmo ? hit_handle(v, e.position, *gizmo, selection_.active(), kPickRadius) : std::nullopt;
    if (handle && !handle->is_centre() && vertex_before_handle(e.position, *gizmo, *handle)) handle.reset();
    if (handle) {  // the drag takes the events until the button is released (ui/tools/handle_drag_tool.h)
      start_tool([&](ToolContext& ctx) {
        return HandleDragTool::start(ctx, *handle, view_.draw.sigma_scale, e.position, view_.common_frame,
                                     gizmo->centre);
      });
    } else {
      mode_ = Mode::click;
    }
    return;
  }
  mode_ = input_.shift() ? Mode::pan : Mode::orbit;
}

void EditorApp::release(const InputEvent& e) {
  if (mode_ == Mode::none || e.button != mode_button_) return;
  // Selecting (ui/editing/pointer_selection.h): in vertex mode the vertex or ellipsoid picked.
  const Viewport v = viewport();
  const PointerScene scene = pointer_scene(v);
  const auto say = [this](const SelectionNote& note) {
    if (!note.text.empty()) set_status(note.text, note.error);
  };
  if (mode_ == Mode::click) {
    if (input_.ctrl() && !input_.shift())
      say(path_select(selection_, scene, e.position, select_mode_ == SelectMode::face ? -1 : pick(e.position)));
    else
      click_select(selection_, scene, e.position, select_mode_ == SelectMode::vertex ? pick(e.position) : -1,
                   input_.shift());
  } else if (mode_ == Mode::box) {
    box_select(selection_, scene, hidden_.elements(), press_pixel_, e.position, input_.shift(), input_.ctrl(),
               select_through_);
  } else if (alt_press_ && (mode_ == Mode::orbit || mode_ == Mode::pan) &&
             glm::length(e.position - press_pixel_) <= kBoxThreshold) {  // Alt+click, Shift+Alt+click adds
    if (input_.ctrl())
      say(ring_select(selection_, scene, e.position, input_.shift()));  // Ctrl+Alt+click
    else
      say(loop_select(selection_, scene, e.position, input_.shift()));
  } else if (mode_ == Mode::pan && e.button == 1 && glm::length(e.position - press_pixel_) <= kBoxThreshold) {
    place_cursor(e.position);  // Shift+right click
  }
  mode_ = Mode::none;
}

void EditorApp::follow_cursor() {
  const glm::vec2 cursor = input_.cursor, delta = cursor - last_cursor_;
  switch (mode_) {
    case Mode::orbit:
      orbit(camera_, delta);
      break;
    case Mode::pan:
      pan(camera_, delta, viewport().height);
      break;
    case Mode::click:
      if (glm::length(cursor - press_pixel_) > kBoxThreshold) mode_ = Mode::box;
      break;
    case Mode::box:
    case Mode::none:
      break;
  }
  last_cursor_ = cursor;
}

void EditorApp::draw_selection() const {
  const ImDrawData* d = ImGui::GetDrawData();
  const float scale = d->FramebufferScale.x;  // as wide as the panels' lines at any scale
  const int width = int(d->DisplaySize.x * scale), height = int(d->DisplaySize.y * d->FramebufferScale.y);
  SelectedElements::Style lines;
  lines.edge_width *= scale, lines.outline_width *= scale;
  selected_elements_->draw(width, height, camera_, lines);
  VertexDots::Style dots;
  dots.diameter *= scale;
  selection_dots_->draw(width, height, camera_, dots);
}

void EditorApp::draw_handles_and_box() {
  const Viewport v = viewport();
  ImDrawList* draw = ImGui::GetBackgroundDrawList();  // over the 3D view, under the panels
  std::optional<HandleFrame> gizmo;
  std::optional<Handle> lit;
  if (const auto held = tool_ ? tool_->gizmo(v) : std::nullopt) {  // a drag's, its handle lit
    gizmo = held->frame;
    lit = held->lit;
  } else {
    if (!shown_->preview()) gizmo = gizmo_frame(v);  // none over a modal tool's preview: it is of the mesh before
    if (gizmo && mode_ == Mode::none && !ImGui::GetIO().WantCaptureMouse)
      lit = hit_handle(v, input_.cursor, *gizmo, selection_.active(), kPickRadius);
  }
  if (view_.draw.mesh_lines)
    draw_crease_overlay(*draw, v, shown_->edited(document_.mesh()), shown_->preview() ? nullptr : &hidden_.elements());
  if (select_mode_ != SelectMode::vertex) {
    // A preview that keeps the document's selection (a crease's) shows its edges; one of its own (a
    // bevel's new faces) is of vertices, its edges those with both ends selected.
    // In face mode the faces' outlines stand for their edges.
    const bool kept = !shown_->preview() || shown_->preview_selection() == selection_.vertices();
    const CovarianceMesh& shown = shown_->edited(document_.mesh());
    const bool faces = select_mode_ == SelectMode::face;
    const std::vector<EdgeEnds> edges = faces  ? std::vector<EdgeEnds>{}
                                        : kept ? selection_.edges(shown)
                                               : edges_within(shown, shown_->preview_selection());
    const std::vector<int> selected_faces = !faces ? std::vector<int>{}
                                            : kept ? selection_.faces(shown)
                                                   : faces_within(shown, shown_->preview_selection());
    selected_elements_->set_elements(shown, edges, selected_faces, shown_->renderer().frame());
  } else {
    selected_elements_->set_elements(document_.mesh(), {}, {}, shown_->renderer().frame());
  }
  selection_dots_->set_vertices(document_.mesh(), selection_.vertices(), shown_->renderer().frame());
  draw->AddCallback(
      [](const ImDrawList*, const ImDrawCmd* command) {
        static_cast<const EditorApp*>(command->UserCallbackData)->draw_selection();
      },
      this);
  draw->AddCallback(ImDrawCallback_ResetRenderState, nullptr);
  draw_handle_overlay(*draw, v, gizmo, lit);
  gizmo_box_.reset();
  if (gizmo) {  // the gizmo's extent on screen, its dots included
    for (int k = -1; k < 6; ++k)
      if (const auto p =
              visible_pixel(v.camera, v.width, v.height, k < 0 ? gizmo->centre : gizmo->end(k / 2, k % 2 ? -1 : 1))) {
        const ScreenBox dot{glm::vec2(*p) - glm::vec2(10.0f), glm::vec2(*p) + glm::vec2(10.0f)};
        gizmo_box_ =
            gizmo_box_ ? ScreenBox{glm::min(gizmo_box_->min, dot.min), glm::max(gizmo_box_->max, dot.max)} : dot;
      }
  }
  if (mode_ == Mode::box) {
    const ImVec2 a(press_pixel_.x, press_pixel_.y), b(input_.cursor.x, input_.cursor.y);
    draw->AddRectFilled(a, b, IM_COL32(90, 150, 255, 40));
    draw->AddRect(a, b, IM_COL32(90, 150, 255, 220));
  }
}

}  // namespace gps
