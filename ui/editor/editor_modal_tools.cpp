// The editor's modal tools: Blender's G / S / R transforms of the selected Gaussians, and the tools
// that follow the mouse after a Mesh operation: extrude (a move along the extrusion's normal), loop
// cut (a ring previewed under the cursor, then a slide); the events of all of them, inset
// (ui/editor/editor_inset_tool.cpp) and crease (ui/editor/editor_crease_tool.cpp) included, and their drawing.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "core/support/error.h"
#include "core/mesh/mesh_connectivity.h"
#include "core/modelling/affine_transform.h"
#include "core/modelling/bridge.h"
#include "core/modelling/delete_elements.h"
#include "core/modelling/edge_operations.h"
#include "core/modelling/extrude.h"
#include "core/modelling/fill.h"
#include "core/modelling/loop_cut.h"
#include "core/modelling/merge_vertices.h"
#include "core/modelling/mesh_queries.h"
#include "core/modelling/operation_words.h"
#include "core/modelling/primitives.h"
#include "core/modelling/subdivide_mesh.h"
#include "ui/editing/crease_tool.h"
#include "ui/editor/editor_app.h"

namespace gps {

namespace {

constexpr float kEdgePickPixels = 40.0f;  // how near the cursor an edge must be for a loop cut

bool is_enter(int key) { return key == GLFW_KEY_ENTER || key == GLFW_KEY_KP_ENTER; }

// A typed number's characters (digits, point, minus).
bool is_number_char(unsigned c) { return (c >= '0' && c <= '9') || c == '.' || c == '-'; }

// The area-weighted normal of faces (Newell's sums), zero when they have no area.
Vec3 faces_normal(const CovarianceMesh& mesh, const std::vector<int>& faces) {
  Vec3 sum = Vec3::Zero();
  for (const int f : faces) {
    std::vector<Vec3> corners;
    for (const auto v : mesh.mesh.fv_range(mesh.mesh.face_handle(unsigned(f))))
      corners.push_back(mesh.mean(size_t(v.idx())));
    for (size_t i = 0; i < corners.size(); ++i) sum += corners[i].cross(corners[(i + 1) % corners.size()]);
  }
  return sum.norm() > 0 ? Vec3(sum.normalized()) : Vec3::Zero();
}

std::optional<double> parse_number(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (!end || *end != '\0' || !std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace

// ---- G / S / R ----

void EditorApp::start_transform(TransformKind kind) {
  if (modal_active() || mode_ != Mode::none || selection_.empty()) return;
  document_.begin_edit();
  transform_.emplace(kind, document_.mesh(), selection_.vertices(), selection_.active(), transform_pivot_, viewport(),
                     input_.cursor);
  transform_folds_ = false;
  std::vector<Vec3> means(document_.mesh().n_vertices());
  for (size_t v = 0; v < means.size(); ++v) means[v] = document_.mesh().mean(v);
  reach_ = edit_reach(means, transform_->vertices(), reach_options_);
  update_transform();
}

void EditorApp::update_transform() {
  const size_t clamped =
      apply_transform(document_, *transform_, reach_, reach_options_.mirror_axis, view_.transform_gaussians);
  status_ =
      transform_->describe() +
      (reach_.size() > transform_->vertices().size() ? "  (" + std::to_string(reach_.size()) + " vertices)" : "") +
      (view_.transform_gaussians ? "" : "  (positions only)") +
      (clamped ? "  (" + count_of(clamped, "Gaussian", "Gaussians") + " held at the flatness floor)" : "");
  status_error_ = false;
}

void EditorApp::end_transform(bool keep) {
  if (!keep) {
    document_.cancel_edit();
    set_status(transform_folds_ ? "move cancelled (the extrusion stays; Ctrl+Z removes it)" : "transform cancelled",
               false);
  } else if (transform_folds_) {
    document_.commit_edit_into_last_operation(selection_.vertices());
    status_ = "extrude: " + last_summary_;  // shown again, not printed again: run_operation printed it
    status_error_ = false;
  } else {
    const std::string done = transform_->describe().substr(0, transform_->describe().find("  (")) +
                             (view_.transform_gaussians ? "" : "  (positions only)");
    // Vertices a mirror (negative determinant) carried: the parts they make up whole get their faces
    // reversed with them, as Blender does, so that the surface stays outward.
    std::vector<int> mirrored_vertices;
    std::vector<std::pair<int, Gaussian>> moved;
    for (const ReachedVertex& r : reach_) {
      AffineMap map = transform_->map(r.source, r.weight);
      if (r.mirrored) map = mirrored(map, reach_options_.mirror_axis);
      if (map.linear.determinant() < 0) mirrored_vertices.push_back(r.vertex);
      moved.push_back(
          {r.vertex, {document_.mesh().mean(size_t(r.vertex)), document_.mesh().covariance(size_t(r.vertex))}});
    }
    if (mirrored_vertices.empty()) {
      document_.commit_edit();
      set_status(done, false);
    } else {
      // One undo step that replaces the mesh: the moved Gaussians and the reversed faces together.
      std::sort(mirrored_vertices.begin(), mirrored_vertices.end());
      document_.cancel_edit();
      transform_.reset();
      const std::vector<int> selected = selection_.vertices();
      run_operation(done, [&](const CovarianceMesh& mesh) {
        MeshArrays a = arrays_of(mesh);
        for (const auto& [v, g] : moved) a.means[size_t(v)] = g.mean, a.covariances[size_t(v)] = g.covariance;
        reverse_parts_within(a, mirrored_vertices);
        return Modelled{build_mesh(a), selected, "mirrored: the faces it moved whole reversed to stay outward"};
      });
    }
  }
  transform_.reset();
  transform_folds_ = false;
}

// ---- Extrude ----

void EditorApp::start_extrude() {
  const std::vector<int> selected = selection_.vertices();
  if (!run_operation("extrude", [&](const CovarianceMesh& m) { return extrude_vertices(m, selected, Vec3::Zero()); }))
    return;
  // Then a move of the new vertices: along the normal of the extruded faces, free for edges and vertices.
  const Vec3 normal = faces_normal(document_.mesh(), faces_within(document_.mesh(), selection_.vertices()));
  document_.begin_edit();
  transform_.emplace(TransformKind::grab, document_.mesh(), selection_.vertices(), selection_.active(),
                     TransformPivot::median, viewport(), input_.cursor);
  if (normal != Vec3::Zero()) transform_->constrain_direction(normal, "the normal");
  transform_folds_ = true;
  reach_.clear();  // the move is of the new vertices only (their copies lie under them)
  for (size_t i = 0; i < transform_->vertices().size(); ++i)
    reach_.push_back({transform_->vertices()[i], 1.0, i, false});
  update_transform();
}

// ---- Loop cut ----

std::optional<std::array<int, 2>> EditorApp::edge_under(glm::vec2 cursor) const {
  const Viewport v = viewport();
  const CovarianceMesh& mesh = document_.mesh();
  const Vec3 eye = to_vec(v.camera.eye_double()), forward = to_vec(v.camera.target) - eye;
  const auto faces_camera = [&](OpenMesh::FaceHandle f) {
    if (!f.is_valid()) return false;
    std::vector<int> corners;
    for (const auto c : mesh.mesh.fv_range(f)) corners.push_back(c.idx());
    std::vector<int> one = {f.idx()};
    const Vec3 n = faces_normal(mesh, one), c = centre_of_vertices(mesh, corners);
    return v.camera.orthographic ? n.dot(forward) < 0 : n.dot(eye - c) > 0;
  };
  std::optional<std::array<int, 2>> best;
  float nearest = kEdgePickPixels;
  for (const auto e : mesh.mesh.edges()) {
    const auto h = mesh.mesh.halfedge_handle(e, 0);
    if (!faces_camera(mesh.mesh.face_handle(h)) && !faces_camera(mesh.mesh.opposite_face_handle(h))) continue;
    const int a = mesh.mesh.from_vertex_handle(h).idx(), b = mesh.mesh.to_vertex_handle(h).idx();
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

void EditorApp::start_loop_cut() {
  if (modal_active() || mode_ != Mode::none) return;
  loop_cut_.emplace();
  hover_loop_cut(input_.cursor);
  status_ = "loop cut: point at an edge; the wheel sets the cuts, click to cut, Esc cancels";
  status_error_ = false;
}

void EditorApp::hover_loop_cut(glm::vec2 cursor) {
  LoopCutTool& tool = *loop_cut_;
  tool.ring = {};
  const auto edge = edge_under(cursor);
  if (!edge) return;
  try {
    tool.ring = edge_ring(document_.mesh(), (*edge)[0], (*edge)[1]);
  } catch (const Error&) {
    return;
  }
}

void EditorApp::confirm_loop_cut() {
  LoopCutTool& tool = *loop_cut_;
  if (tool.ring.edges.empty()) return;
  const auto [a, b] = tool.ring.edges.front();
  tool.base = std::make_shared<const CovarianceMesh>(document_.mesh());
  try {
    install(loop_cut(*tool.base, a, b, tool.cuts));
  } catch (const Error& e) {  // refused: nothing changed
    operation_note(std::string("loop cut refused: ") + e.what(), true);
    loop_cut_.reset();
    return;
  }
  tool.sliding = true;
  tool.start_cursor = input_.cursor;
  document_.begin_edit();
  status_ = "loop cut: move to slide, click or Enter to confirm, Esc keeps it in the middle";
}

void EditorApp::slide_loop_cut(glm::vec2 cursor) {
  LoopCutTool& tool = *loop_cut_;
  const auto [a, b] = tool.ring.edges.front();
  const Viewport v = viewport();
  const auto pa = project_to_pixel(v.camera, v.width, v.height, tool.base->mean(size_t(a)));
  const auto pb = project_to_pixel(v.camera, v.width, v.height, tool.base->mean(size_t(b)));
  if (!pa || !pb) return;
  const glm::vec2 d = glm::vec2(*pb) - glm::vec2(*pa);
  if (glm::dot(d, d) < 1.0f) return;
  const double slide = std::clamp(2.0 * double(glm::dot(cursor - tool.start_cursor, d) / glm::dot(d, d)), -0.95, 0.95);
  try {
    const Modelled slid = loop_cut(*tool.base, a, b, tool.cuts, slide);
    const CovarianceMesh& mesh = document_.mesh();
    if (slid.mesh.n_vertices() != mesh.n_vertices()) return;
    for (size_t i = 0; i < mesh.n_vertices(); ++i) {
      if (slid.mesh.mean(i) != document_.start_mean(int(i)) || mesh.mean(i) != slid.mesh.mean(i))
        document_.set_mean(int(i), slid.mesh.mean(i));
      if (slid.mesh.covariance(i) != document_.start_covariance(int(i)) ||
          mesh.covariance(i) != slid.mesh.covariance(i))
        document_.set_covariance(int(i), slid.mesh.covariance(i));
    }
    char text[96];
    std::snprintf(text, sizeof text, "loop cut: slide %.3f (click or Enter confirms, Esc keeps it in the middle)",
                  slide);
    status_ = text;
  } catch (const Error&) {
  }
}

void EditorApp::end_loop_cut(bool keep) {
  if (loop_cut_->sliding) {
    if (keep)
      document_.commit_edit_into_last_operation(selection_.vertices());
    else
      document_.cancel_edit();
    operation_note("loop cut: " + last_summary_, false);
  } else {
    set_status("loop cut cancelled", false);
  }
  loop_cut_.reset();
}

// ---- Events of the modal tools ----

bool EditorApp::modal_event(const InputEvent& e) {
  if (!modal_active()) return false;
  const bool press_left = e.type == InputEvent::Type::press && e.button == 0;
  const bool key = e.type == InputEvent::Type::key_press;
  const bool confirm = press_left || (key && is_enter(e.key));
  const bool cancel = (e.type == InputEvent::Type::press && e.button == 1) || (key && e.key == GLFW_KEY_ESCAPE);
  if (transform_) {
    if (confirm || cancel) {
      end_transform(confirm);
      return true;
    }
    if (e.type == InputEvent::Type::move) {
      if (transform_->typed().empty()) transform_->move_cursor(e.position, viewport());
    } else if (key && (e.key == GLFW_KEY_X || e.key == GLFW_KEY_Y || e.key == GLFW_KEY_Z)) {
      transform_->constrain_axis(e.key - GLFW_KEY_X, input_.shift());
      transform_->move_cursor(input_.cursor, viewport());
    } else if (key && e.key == GLFW_KEY_BACKSPACE && !transform_->typed().empty()) {
      std::string typed = transform_->typed();
      typed.pop_back();
      transform_->set_typed(typed);
    } else if (e.type == InputEvent::Type::text && is_number_char(e.codepoint)) {
      transform_->set_typed(transform_->typed() + char(e.codepoint));
    } else if (e.type == InputEvent::Type::scroll && reach_options_.proportional && !transform_folds_) {
      reach_options_.radius *= std::pow(1.15, double(e.steps));
      std::vector<Vec3> means(document_.mesh().n_vertices());
      for (size_t v = 0; v < means.size(); ++v) means[v] = document_.start_mean(int(v));
      document_.revert_edit();
      reach_ = edit_reach(means, transform_->vertices(), reach_options_);
    } else if (e.type != InputEvent::Type::release) {
      return e.type != InputEvent::Type::scroll;  // the wheel still zooms
    }
    update_transform();
    return true;
  }
  if (loop_cut_) {
    if (cancel) {
      end_loop_cut(false);
    } else if (confirm) {
      if (loop_cut_->sliding)
        end_loop_cut(true);
      else
        confirm_loop_cut();
    } else if (e.type == InputEvent::Type::move) {
      if (loop_cut_->sliding)
        slide_loop_cut(e.position);
      else
        hover_loop_cut(e.position);
    } else if (e.type == InputEvent::Type::scroll && !loop_cut_->sliding) {
      loop_cut_->cuts = std::clamp(loop_cut_->cuts + (e.steps > 0 ? 1 : -1), 1, 64);
      status_ = "loop cut: " + std::to_string(loop_cut_->cuts) + " cuts (wheel), click to cut, Esc cancels";
    } else if (e.type == InputEvent::Type::scroll) {
      return false;
    }
    return true;
  }
  if (inset_) {
    if (confirm || cancel) {
      end_inset(confirm);
    } else if (e.type == InputEvent::Type::move && inset_->typed.empty()) {
      follow_inset(e.position);
    } else if (e.type == InputEvent::Type::text && is_number_char(e.codepoint)) {
      inset_->typed += char(e.codepoint);
      if (const auto t = parse_number(inset_->typed)) update_inset(*t);
    } else if (key && e.key == GLFW_KEY_BACKSPACE && !inset_->typed.empty()) {
      inset_->typed.pop_back();
      if (const auto t = parse_number(inset_->typed)) update_inset(*t);
    } else if (e.type == InputEvent::Type::scroll) {
      return false;
    }
    return true;
  }
  if (crease_) {
    if (confirm || cancel) {
      end_crease(confirm);
    } else if (e.type == InputEvent::Type::move && crease_->typed.empty()) {
      preview_crease(sharpness_after_drag(crease_->start, e.position.x - crease_->start_cursor.x, viewport().width));
    } else if (e.type == InputEvent::Type::text && is_number_char(e.codepoint)) {
      crease_->typed += char(e.codepoint);
      if (const auto t = parse_number(crease_->typed)) preview_crease(*t);
    } else if (key && e.key == GLFW_KEY_BACKSPACE && !crease_->typed.empty()) {
      crease_->typed.pop_back();
      const auto t = parse_number(crease_->typed);
      preview_crease(t ? *t : crease_->start);
    } else if (e.type == InputEvent::Type::scroll) {
      return false;
    }
    return true;
  }
  return false;
}

}  // namespace gps
