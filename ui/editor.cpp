#include "ui/editor.h"

#include <glad/gl.h>

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/samples.h"
#include "render/gl_context.h"
#include "render/gpu_pass_timer.h"
#include "render/matcap.h"
#include "render/picking.h"
#include "render/window_context.h"
#include "ui/axis_handles.h"
#include "ui/camera_control.h"
#include "ui/editor_document.h"
#include "ui/event_script.h"
#include "ui/file_browser.h"
#include "ui/glfw_input.h"
#include "ui/handle_overlay.h"
#include "ui/help_overlay.h"
#include "ui/input_events.h"
#include "ui/inspector_panel.h"
#include "ui/recent_files.h"
#include "ui/selection.h"
#include "ui/status_bar.h"
#include "ui/statistics_overlay.h"
#include "ui/view_options.h"
#include "ui/view_panel.h"

namespace gps {

namespace {

using Clock = std::chrono::steady_clock;

constexpr const char* kDefaultSample = "cone-pointy";
constexpr float kPickRadius = 8.0f;       // window pixels
constexpr float kBoxThreshold = 4.0f;     // pixels a left press moves before it becomes a box
constexpr size_t kMaxHandleVertices = 64;  // more selected: handles on the active vertex only
constexpr size_t kMaxFacesWithLines = 5000;  // larger meshes open with the base-mesh lines off
const std::vector<std::string> kMeshExtensions = {".ply", ".obj", ".off", ".stl"};
const std::vector<std::string> kImageExtensions = {".png", ".jpg", ".jpeg", ".exr", ".tif", ".tiff", ".hdr"};

// What a confirmation about unsaved changes holds back.
struct Action {
  enum class Kind { none, quit, open_file, open_sample } kind = Kind::none;
  std::string argument;
};

class Editor {
public:
  explicit Editor(const EditorOptions& options);
  ~Editor();
  Editor(const Editor&) = delete;
  Editor& operator=(const Editor&) = delete;
  int run();

private:
  // Input.
  void push_live(InputEvent e);
  void handle_event(const InputEvent& e);
  void handle_key(int key);
  void press(const InputEvent& e);
  void release(const InputEvent& e);
  void follow_cursor();
  int pick(glm::vec2 pixel) const;
  std::vector<int> handle_vertices() const;
  Viewport viewport() const;
  // Frames.
  void frame();
  void draw_ui();
  void draw_menu();
  void draw_handles_and_box();
  void draw_unsaved_prompt();
  void handle_browser_result();
  void render_and_present();
  bool script_finished();
  // Actions.
  void request(Action action);
  void perform(const Action& action);
  void open_file(const std::string& path);
  void open_sample(const std::string& name);
  bool save();  // false: a file name is being asked for
  void save_to(const std::string& path);
  void undo_redo(bool undo);
  void mesh_replaced();
  void mark_changed(const std::vector<int>& vertices);
  void write_screenshot(const std::string& path);
  void write_statistics(const std::string& path);
  void set_status(const std::string& message, bool error);
  void update_title();

  EditorOptions options_;
  WindowContext window_;
  GlfwInputForwarder input_forwarder_;
  std::unique_ptr<SurfaceRenderer> renderer_;
  std::unique_ptr<GpuPassTimer> timer_;
  std::unique_ptr<RenderTarget> target_;
  EditorDocument document_;
  Selection selection_;
  Camera camera_;
  ViewOptions view_;
  InspectorPanel inspector_;
  FileBrowser browser_;
  enum class BrowserPurpose { open_mesh, save_mesh, load_matcap } browser_purpose_ = BrowserPurpose::open_mesh;
  RecentFiles recent_;
  FrameClock clock_;

  InputQueue queue_;
  InputState input_;
  std::optional<EventScript> script_;
  std::optional<EventRecorder> recorder_;
  int finishing_frames_ = 0;

  enum class Mode { none, click, box, orbit, pan, handle } mode_ = Mode::none;
  int mode_button_ = 0;
  glm::vec2 press_pixel_{0.0f}, last_cursor_{0.0f};
  std::optional<HandleDrag> drag_;
  std::optional<VertexEdit> drag_edit_;

  std::vector<int> changed_;  // vertices whose Gaussians changed this frame
  Clock::time_point frame_input_time_{}, last_frame_time_ = Clock::now();
  Action pending_;
  bool prompt_unsaved_ = false, after_save_perform_ = false, quit_ = false;
  std::string screenshot_request_;
  std::string status_;
  bool status_error_ = false;
  std::string last_title_;
  int swap_interval_ = -1;
};

Editor::Editor(const EditorOptions& options)
    : options_(options),
      window_(options.width, options.height, "gpsurf", true),
      input_forwarder_(window_.window(), [this](InputEvent e) { push_live(std::move(e)); },
                       [this] { request({Action::Kind::quit, ""}); }),
      recent_(RecentFiles::default_store()) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // the layout starts the same every time (scripted sessions rely on it)
  map_imgui_keys(io);
  // DejaVu (Debian's fonts-dejavu-core) covers the Greek letters and symbols the panels use.
  const char* font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  static const ImWchar ranges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2010, 0x22FF, 0};
  if (!std::filesystem::exists(font) || !io.Fonts->AddFontFromFileTTF(font, 15.0f, nullptr, ranges)) io.Fonts->AddFontDefault();
  ImGui::StyleColorsDark();
  ImGui_ImplOpenGL3_Init("#version 450 core");
  renderer_ = std::make_unique<SurfaceRenderer>();
  timer_ = std::make_unique<GpuPassTimer>();
  renderer_->set_pass_timer(timer_.get());
  renderer_->set_collect_statistics(true);
  view_.vsync = options.vsync;
  if (!options.play.empty()) script_ = EventScript::load(options.play);
  if (!options.record.empty()) recorder_.emplace();
  if (options.file.empty()) {
    open_sample(kDefaultSample);
  } else {  // no mesh to keep yet: a file that does not load ends the program (one line, exit 1)
    document_.open(options.file);
    recent_.add(document_.source_path());
    mesh_replaced();
  }
}

Editor::~Editor() {
  renderer_.reset();
  timer_.reset();
  target_.reset();
  ImGui_ImplOpenGL3_Shutdown();
  ImGui::DestroyContext();
}

void Editor::push_live(InputEvent e) {
  if (!script_) queue_.push(std::move(e));  // a replay is not disturbed by the real pointer
}

Viewport Editor::viewport() const {
  Viewport v;
  v.camera = camera_;
  glfwGetWindowSize(window_.window(), &v.width, &v.height);
  v.width = std::max(1, v.width);
  v.height = std::max(1, v.height);
  return v;
}

// ---------------------------------------------------------------------------------------------
// Input

void Editor::handle_event(const InputEvent& e) {
  const ImGuiIO& io = ImGui::GetIO();
  switch (e.type) {
    case InputEvent::Type::press:
      if (!io.WantCaptureMouse && !prompt_unsaved_) press(e);
      break;
    case InputEvent::Type::release: release(e); break;
    case InputEvent::Type::scroll:
      if (!io.WantCaptureMouse) {
        const Viewport v = viewport();
        std::optional<glm::vec3> anchor;
        if (target_) anchor = surface_point(*target_, e.position * glm::vec2(float(target_->width()) / float(v.width),
                                                                              float(target_->height()) / float(v.height)));
        zoom_to_cursor(camera_, e.steps, v.width, v.height, e.position, anchor);
      }
      break;
    case InputEvent::Type::key_press:
      if (!io.WantCaptureKeyboard && !browser_.is_open()) handle_key(e.key);
      break;
    case InputEvent::Type::drop:
      if (!e.paths.empty()) request({Action::Kind::open_file, e.paths.front()});
      break;
    case InputEvent::Type::move:
    case InputEvent::Type::key_release:
    case InputEvent::Type::text: break;
  }
}

void Editor::handle_key(int key) {
  const bool ctrl = input_.ctrl(), shift = input_.shift();
  if (ctrl && key == GLFW_KEY_Z) undo_redo(!shift);
  else if (ctrl && key == GLFW_KEY_Y) undo_redo(false);
  else if (ctrl && key == GLFW_KEY_S && shift) save_to("");
  else if (ctrl && key == GLFW_KEY_S) save();
  else if (ctrl && key == GLFW_KEY_O) request({Action::Kind::open_file, ""});
  else if (ctrl && key == GLFW_KEY_Q) request({Action::Kind::quit, ""});
  else if (ctrl && key == GLFW_KEY_A) selection_.select_all(document_.mesh.n_vertices());
  else if (key == GLFW_KEY_ESCAPE || (input_.alt() && key == GLFW_KEY_A)) selection_.clear();
  else if (key == GLFW_KEY_F && !ctrl) {
    const double radius = 0.05 * bounding_box_diagonal(document_.mesh);
    if (selection_.empty()) camera_ = frame_mesh(document_.mesh, camera_.yaw_degrees, camera_.pitch_degrees);
    else camera_ = frame_points(camera_, document_.mesh, selection_.vertices(), radius);
  } else if (key == GLFW_KEY_HOME) camera_ = frame_mesh(document_.mesh, camera_.yaw_degrees, camera_.pitch_degrees);
  else if (key == GLFW_KEY_F1) view_.show_help = !view_.show_help;
  else if (key == GLFW_KEY_F12) {
    char name[64];
    const std::time_t now = std::time(nullptr);
    std::strftime(name, sizeof name, "gpsurf-%Y%m%d-%H%M%S.png", std::localtime(&now));
    screenshot_request_ = name;
  }
}

std::vector<int> Editor::handle_vertices() const {
  if (selection_.vertices().size() <= kMaxHandleVertices) return selection_.vertices();
  return {selection_.active()};
}

int Editor::pick(glm::vec2 pixel) const {
  const Viewport v = viewport();
  const int vertex = pick_vertex(v.camera, v.width, v.height, pixel, document_.mesh, kPickRadius);
  if (vertex >= 0 || !view_.draw.ellipsoids) return vertex;
  return pick_ellipsoid(v.camera, v.width, v.height, pixel, document_.mesh, view_.draw.sigma_scale);
}

void Editor::press(const InputEvent& e) {
  if (mode_ != Mode::none) return;
  mode_button_ = e.button;
  press_pixel_ = last_cursor_ = e.position;
  if (e.button == 0 && !input_.alt()) {
    const Viewport v = viewport();
    if (const auto handle = hit_handle(v, e.position, document_.mesh, handle_vertices(), view_.draw.sigma_scale, kPickRadius)) {
      drag_.emplace(document_.mesh, selection_.vertices(), *handle, view_.draw.sigma_scale, v, e.position);
      drag_edit_ = EditHistory::begin(document_.mesh, selection_.vertices());
      mode_ = Mode::handle;
    } else {
      mode_ = Mode::click;
    }
    return;
  }
  mode_ = input_.shift() ? Mode::pan : Mode::orbit;
}

void Editor::release(const InputEvent& e) {
  if (mode_ == Mode::none || e.button != mode_button_) return;
  const Viewport v = viewport();
  if (mode_ == Mode::click) {
    selection_.click(pick(e.position), input_.shift());
  } else if (mode_ == Mode::box) {
    selection_.select(vertices_in_box(v.camera, v.width, v.height, press_pixel_, e.position, document_.mesh), input_.shift());
  } else if (mode_ == Mode::handle) {
    const VertexEdit& before = *drag_edit_;
    bool moved = false;
    for (size_t i = 0; i < before.vertices.size(); ++i) {
      const size_t vertex = size_t(before.vertices[i]);
      moved = moved || document_.mesh.mean(vertex) != before.means_before[i] ||
              document_.mesh.covariance(vertex) != before.covariances_before[i];
    }
    if (moved) document_.history.commit(std::move(*drag_edit_), document_.mesh);  // one undo step per drag
    drag_.reset();
    drag_edit_.reset();
  }
  mode_ = Mode::none;
}

void Editor::follow_cursor() {
  const glm::vec2 cursor = input_.cursor, delta = cursor - last_cursor_;
  switch (mode_) {
    case Mode::orbit: orbit(camera_, delta); break;
    case Mode::pan: pan(camera_, delta, viewport().height); break;
    case Mode::click:
      if (glm::length(cursor - press_pixel_) > kBoxThreshold) mode_ = Mode::box;
      break;
    case Mode::handle:
      if (delta != glm::vec2(0.0f) && drag_->update(document_.mesh, viewport(), cursor)) mark_changed(drag_->vertices());
      break;
    case Mode::box:
    case Mode::none: break;
  }
  last_cursor_ = cursor;
}

// ---------------------------------------------------------------------------------------------
// Frames

int Editor::run() {
  while (!quit_) {
    frame();
    if (script_finished()) break;
  }
  if (recorder_) recorder_->save(options_.record);
  if (!options_.stats.empty()) write_statistics(options_.stats);
  return 0;
}

bool Editor::script_finished() {
  const bool scripted = script_ || !options_.screenshot.empty() || !options_.save.empty();
  if (!scripted || (script_ && !script_->done())) return false;
  // Two more frames after the last event: auto-sized ImGui windows settle on their second frame.
  if (++finishing_frames_ < 3) return false;
  if (!options_.save.empty()) save_to(options_.save);
  return true;
}

void Editor::frame() {
  glfwPollEvents();
  const int swap_interval = view_.vsync && !script_ ? 1 : 0;  // replays run as fast as they can
  if (swap_interval != swap_interval_) glfwSwapInterval(swap_interval_ = swap_interval);
  frame_input_time_ = Clock::now();
  const std::vector<InputEvent> events = script_ ? script_->next_frame() : queue_.take_frame();
  if (recorder_) recorder_->record_frame(events);
  for (const InputEvent& e : events) input_.apply(e);

  ImGuiIO& io = ImGui::GetIO();
  int width = 0, height = 0, fb_width = 0, fb_height = 0;
  glfwGetWindowSize(window_.window(), &width, &height);
  window_.framebuffer_size(fb_width, fb_height);
  io.DisplaySize = ImVec2(float(width), float(height));
  if (width > 0 && height > 0) io.DisplayFramebufferScale = ImVec2(float(fb_width) / float(width), float(fb_height) / float(height));
  io.DeltaTime = script_ ? 1.0f / 60.0f : std::clamp(std::chrono::duration<float>(frame_input_time_ - last_frame_time_).count(), 1e-4f, 1.0f);
  last_frame_time_ = frame_input_time_;
  feed_imgui(io, input_, events);
  ImGui_ImplOpenGL3_NewFrame();
  ImGui::NewFrame();

  for (const InputEvent& e : events) handle_event(e);
  follow_cursor();
  draw_ui();
  ImGui::Render();
  render_and_present();
}

void Editor::mark_changed(const std::vector<int>& vertices) { changed_.insert(changed_.end(), vertices.begin(), vertices.end()); }

void Editor::render_and_present() {
  int fb_width = 0, fb_height = 0;
  window_.framebuffer_size(fb_width, fb_height);
  const bool edited = !changed_.empty();
  if (edited) {  // the edit path: only these vertices' 9D values and the stencil rows reading them
    std::sort(changed_.begin(), changed_.end());
    changed_.erase(std::unique(changed_.begin(), changed_.end()), changed_.end());
    renderer_->update_vertices(document_.mesh, changed_);
    changed_.clear();
  }
  if (fb_width > 0 && fb_height > 0) {
    if (!target_ || target_->width() != fb_width || target_->height() != fb_height) {
      target_.reset();
      target_ = std::make_unique<RenderTarget>(fb_width, fb_height);
    }
    renderer_->draw(*target_, camera_, view_.draw);
    window_.blit(*target_);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, fb_width, fb_height);
  timer_->begin("UI");
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  timer_->end();
  check_gl_errors("drawing the editor");
  if (!screenshot_request_.empty()) {
    write_screenshot(screenshot_request_);
    screenshot_request_.clear();
  }
  if (finishing_frames_ == 2 && !options_.screenshot.empty()) write_screenshot(options_.screenshot);
  window_.swap_buffers();
  if (edited) {  // edit to frame: until the GPU has finished the frame that shows the edit
    const GLsync fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, GLuint64(2'000'000'000));
    glDeleteSync(fence);
    clock_.edit_shown(frame_input_time_);
  }
  clock_.frame_done();
}

void Editor::write_statistics(const std::string& path) {
  const DrawStatistics draw = renderer_->last_statistics();
  nlohmann::json passes = nlohmann::json::object();
  for (const auto& [pass, ms] : timer_->latest()) passes[pass] = ms;
  const nlohmann::json j = {{"mesh", document_.display_name()},
                            {"faces", document_.mesh.n_faces()},
                            {"patches", draw.patches},
                            {"triangles", draw.triangles},
                            {"gl", window_.description()},
                            {"median_frame_ms", clock_.median_frame_ms()},
                            {"median_edit_to_frame_ms", clock_.median_edit_ms()},
                            {"edits", clock_.edit_count()},
                            {"gpu_pass_ms", passes}};
  write_file_atomically(path, [&j](std::ostream& out) { out << j.dump(2) << "\n"; });
}

void Editor::write_screenshot(const std::string& path) {
  try {
    write_image(path, window_.read_pixels());
    set_status("screenshot written to " + path, false);
  } catch (const Error& e) {
    if (!options_.screenshot.empty()) throw;
    set_status(e.what(), true);
  }
}

// ---------------------------------------------------------------------------------------------
// Panels

void Editor::draw_ui() {
  draw_menu();
  draw_handles_and_box();
  if (view_.show_inspector) mark_changed(inspector_.draw(document_, selection_, &view_.show_inspector));
  if (view_.show_view) {
    const ViewPanelChanges c = draw_view_panel(view_, &view_.show_view);
    if (c.depth) try {
        renderer_->set_mesh(document_.mesh, view_.depth);
      } catch (const Error& e) {  // too deep for the GPU's buffers: the previous plans stay
        set_status(e.what(), true);
      }
    if (c.matcap) renderer_->set_matcap(load_matcap(view_.matcap));
    if (c.load_matcap) {
      browser_purpose_ = BrowserPurpose::load_matcap;
      browser_.open(FileBrowser::Mode::open, "Load MatCap", std::filesystem::current_path().string(), kImageExtensions);
    }
  }
  if (view_.show_statistics) draw_statistics_overlay(clock_, timer_->latest(), renderer_->last_statistics(), &view_.show_statistics);
  draw_help_overlay(&view_.show_help);
  draw_unsaved_prompt();
  handle_browser_result();
  draw_status_bar(document_, selection_.vertices().size(), status_, status_error_);
  update_title();
}

void Editor::draw_menu() {
  if (!ImGui::BeginMainMenuBar()) return;
  if (ImGui::BeginMenu("File")) {
    if (ImGui::MenuItem("Open...", "Ctrl+O")) request({Action::Kind::open_file, ""});
    if (ImGui::BeginMenu("Open sample")) {
      for (const std::string& name : sample_names())
        if (ImGui::MenuItem(name.c_str())) request({Action::Kind::open_sample, name});
      ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Open recent", !recent_.paths().empty())) {
      for (const std::string& path : recent_.paths())
        if (ImGui::MenuItem(path.c_str())) request({Action::Kind::open_file, path});
      ImGui::EndMenu();
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Save", "Ctrl+S")) save();
    if (ImGui::MenuItem("Save As...", "Ctrl+Shift+S")) save_to("");
    if (ImGui::MenuItem("Screenshot", "F12")) handle_key(GLFW_KEY_F12);
    ImGui::Separator();
    if (ImGui::MenuItem("Quit", "Ctrl+Q")) request({Action::Kind::quit, ""});
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Edit")) {
    if (ImGui::MenuItem("Undo", "Ctrl+Z", false, document_.history.can_undo())) undo_redo(true);
    if (ImGui::MenuItem("Redo", "Ctrl+Shift+Z", false, document_.history.can_redo())) undo_redo(false);
    ImGui::Separator();
    if (ImGui::MenuItem("Select all", "Ctrl+A")) selection_.select_all(document_.mesh.n_vertices());
    if (ImGui::MenuItem("Select none", "Escape")) selection_.clear();
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    if (ImGui::MenuItem("Frame all", "Home")) handle_key(GLFW_KEY_HOME);
    if (ImGui::MenuItem("Frame selection", "F")) handle_key(GLFW_KEY_F);
    ImGui::Separator();
    ImGui::MenuItem("Inspector", nullptr, &view_.show_inspector);
    ImGui::MenuItem("View options", nullptr, &view_.show_view);
    ImGui::MenuItem("Statistics", nullptr, &view_.show_statistics);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Help")) {
    ImGui::MenuItem("Mouse and keys", "F1", &view_.show_help);
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
}

void Editor::draw_handles_and_box() {
  const Viewport v = viewport();
  std::optional<Handle> hovered;
  if (mode_ == Mode::handle) hovered = drag_->handle();
  else if (mode_ == Mode::none && !ImGui::GetIO().WantCaptureMouse)
    hovered = hit_handle(v, input_.cursor, document_.mesh, handle_vertices(), view_.draw.sigma_scale, kPickRadius);
  ImDrawList* draw = ImGui::GetBackgroundDrawList();  // over the 3D view, under the panels
  draw_handle_overlay(*draw, v, document_.mesh, selection_.vertices(), handle_vertices(), view_.draw.sigma_scale, hovered);
  if (mode_ == Mode::box) {
    const ImVec2 a(press_pixel_.x, press_pixel_.y), b(input_.cursor.x, input_.cursor.y);
    draw->AddRectFilled(a, b, IM_COL32(90, 150, 255, 40));
    draw->AddRect(a, b, IM_COL32(90, 150, 255, 220));
  }
}

void Editor::draw_unsaved_prompt() {
  if (prompt_unsaved_) {
    ImGui::OpenPopup("Unsaved changes");
    prompt_unsaved_ = false;
  }
  if (!ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ImGui::Text("%s has unsaved changes.", document_.display_name().c_str());
  ImGui::Text("Save them before %s?", pending_.kind == Action::Kind::quit ? "quitting" : "opening another mesh");
  if (ImGui::Button("Save")) {
    ImGui::CloseCurrentPopup();
    after_save_perform_ = true;  // a Save As dialog performs it once the file is written
    if (save()) {
      after_save_perform_ = false;
      perform(pending_);
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("Discard")) {
    ImGui::CloseCurrentPopup();
    perform(pending_);
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
    ImGui::CloseCurrentPopup();
    pending_ = {};
  }
  ImGui::EndPopup();
}

void Editor::handle_browser_result() {
  const bool was_open = browser_.is_open();
  const std::optional<std::string> chosen = browser_.draw();
  if (!chosen) {
    if (was_open && !browser_.is_open()) after_save_perform_ = false, pending_ = {};  // cancelled
    return;
  }
  switch (browser_purpose_) {
    case BrowserPurpose::open_mesh: open_file(*chosen); break;
    case BrowserPurpose::save_mesh:
      save_to(*chosen);
      if (after_save_perform_ && !document_.dirty()) perform(pending_);
      break;
    case BrowserPurpose::load_matcap:
      try {
        renderer_->set_matcap(load_matcap(*chosen));
        view_.matcap = std::filesystem::path(*chosen).filename().string();
      } catch (const Error& e) {
        set_status(e.what(), true);
      }
      break;
  }
  after_save_perform_ = false;
}

// ---------------------------------------------------------------------------------------------
// Actions

void Editor::request(Action action) {
  if (document_.dirty() && action.kind != Action::Kind::none) {
    pending_ = std::move(action);
    prompt_unsaved_ = true;
    return;
  }
  perform(action);
}

void Editor::perform(const Action& action) {
  switch (action.kind) {
    case Action::Kind::quit: quit_ = true; break;
    case Action::Kind::open_file:
      if (!action.argument.empty()) {
        open_file(action.argument);
      } else {  // ask for the file, beside the current one
        browser_purpose_ = BrowserPurpose::open_mesh;
        const std::filesystem::path source = document_.source_path();
        browser_.open(FileBrowser::Mode::open, "Open mesh",
                      source.empty() ? std::filesystem::current_path().string() : source.parent_path().string(), kMeshExtensions);
      }
      break;
    case Action::Kind::open_sample: open_sample(action.argument); break;
    case Action::Kind::none: break;
  }
  pending_ = {};
}

void Editor::open_file(const std::string& path) {
  const EditorDocument previous = document_;
  try {
    document_.open(path);
    mesh_replaced();  // the renderer may refuse the mesh (valence, GPU limits): nothing changed then
  } catch (const Error& e) {  // the current mesh stays
    document_ = previous;
    set_status(e.what(), true);
    return;
  }
  recent_.add(document_.source_path());
  set_status("opened " + document_.source_path(), false);
}

void Editor::open_sample(const std::string& name) {
  document_.open_sample(name);
  mesh_replaced();
  set_status("opened the built-in sample '" + name + "': " + sample_description(name), false);
}

void Editor::mesh_replaced() {
  renderer_->set_mesh(document_.mesh, view_.depth);  // first: it throws before changing anything
  mode_ = Mode::none;
  drag_.reset();
  drag_edit_.reset();
  changed_.clear();
  selection_.clear();
  camera_ = frame_mesh(document_.mesh);
  // Base-mesh lines are drawn over the surface: on a dense mesh they would hide it.
  view_.draw.mesh_lines = document_.mesh.n_faces() <= kMaxFacesWithLines;
}

bool Editor::save() {
  if (!document_.can_save_in_place()) {
    save_to("");
    return false;
  }
  save_to(document_.ply_path());
  return !document_.dirty();
}

void Editor::save_to(const std::string& path) {
  if (path.empty()) {  // Save As: ask for a name, beside the current file
    browser_purpose_ = BrowserPurpose::save_mesh;
    const std::filesystem::path source = document_.source_path();
    const std::string folder = source.empty() ? std::filesystem::current_path().string() : source.parent_path().string();
    const std::string name = source.empty() ? "untitled.ply" : source.stem().string() + ".ply";
    browser_.open(FileBrowser::Mode::save, "Save covariance mesh", folder, {".ply", ".obj"}, name);
    return;
  }
  try {
    document_.save(path);
    recent_.add(document_.source_path());
    set_status("saved " + path, false);
  } catch (const Error& e) {
    if (!options_.save.empty() && path == options_.save) throw;  // a scripted save must not fail quietly
    set_status(e.what(), true);
  }
}

void Editor::undo_redo(bool undo) {
  if (mode_ == Mode::handle) return;  // not in the middle of a drag
  const std::vector<int> changed = undo ? document_.history.undo(document_.mesh) : document_.history.redo(document_.mesh);
  mark_changed(changed);
}

void Editor::set_status(const std::string& message, bool error) {
  status_ = message;
  status_error_ = error;
  (error ? std::cerr : std::cout) << "gpsurf-editor: " << message << std::endl;
}

void Editor::update_title() {
  const std::string title = "gpsurf - " + document_.display_name() + (document_.dirty() ? " *" : "");
  if (title != last_title_) glfwSetWindowTitle(window_.window(), title.c_str());
  last_title_ = title;
}

}  // namespace

int run_editor(const EditorOptions& options) {
  Editor editor(options);
  return editor.run();
}

}  // namespace gps
