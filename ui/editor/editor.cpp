#include "ui/editor/editor.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_opengl3.h>
#include <imgui_internal.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "core/io/atomic_file.h"
#include "core/support/error.h"
#include "render/gl/frame_finite_check.h"
#include "render/gl/gl_context.h"
#include "render/image/image_io.h"
#include "render/image/matcap.h"
#include "render/image/matcap_file.h"
#include "ui/editor/editor_app.h"
#include "ui/settings/editor_settings.h"
#include "ui/overlays/ellipsoid_scope.h"
#include "ui/panels/help_overlay.h"
#include "ui/panels/status_bar.h"
#include "ui/panels/view_panel.h"

namespace gps {

namespace {
constexpr const char* kDefaultSample = "cone-pointy";
const std::vector<std::string> kImageExtensions = {".png", ".jpg", ".jpeg", ".exr", ".tif", ".tiff", ".hdr"};
}  // namespace

EditorApp::EditorApp(const EditorOptions& options)
    : options_(options),
      window_(options.width, options.height, "gpsurf", true),
      input_forwarder_(
          window_.window(),
          [this](InputEvent e) {
            if (!script_) queue_.push(std::move(e));  // a replay is not disturbed by the real pointer
          },
          [this] {
            request({Action::Kind::quit, ""});
          }),
      recent_(RecentFiles::default_store()),
      free_max_(float(options.width), float(options.height)) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  // The panel layout and the View settings are kept in the user's configuration folder.
  config_folder_ = config_folder();
  std::error_code ignored;
  if (!config_folder_.empty()) std::filesystem::create_directories(config_folder_, ignored);
  layout_file_ = config_folder_.empty() ? "" : config_folder_ + "/imgui.ini";
  io.IniFilename = layout_file_.empty() ? nullptr : layout_file_.c_str();
  map_imgui_keys(io);
  // DejaVu (Debian's fonts-dejavu-core) covers the Greek letters and symbols the panels use.
  const char* font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  static const ImWchar ranges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2010, 0x22FF, 0};
  if (!std::filesystem::exists(font) || !io.Fonts->AddFontFromFileTTF(font, 15.0f, nullptr, ranges))
    io.Fonts->AddFontDefault();
  ImGui::StyleColorsDark();
  ImGui_ImplOpenGL3_Init("#version 450 core");
  shown_ = std::make_unique<ShownSurface>();
  target_layer_ = std::make_unique<TargetPointsLayer>();
  selection_dots_ = std::make_unique<VertexDots>();
  selected_elements_ = std::make_unique<SelectedElements>();
  timer_ = std::make_unique<GpuPassTimer>();
  viewport_ = std::make_unique<ViewportFrame>();
  shown_->renderer().set_pass_timer(timer_.get());
  shown_->renderer().set_collect_statistics(true);
  if (const std::string error = load_settings(config_folder_, view_, reach_options_); !error.empty())
    set_status(error, true);
  if (!options.vsync) view_.vsync = false;
  if (options.scheme >= 0) view_.scheme = options.scheme;
  if (options.warren) view_.warren = true;
  if (view_.matcap != "clay") {
    try {
      shown_->renderer().set_matcap(load_matcap(view_.matcap));
    } catch (const Error&) {
      view_.matcap = "clay";  // a MatCap image that is gone
    }
  }
  build_commands();
  if (!options.play.empty()) script_ = EventScript::load(options.play);
  // Interactive: the weld of a whole new surface (llvmpipe's) waits for a pause, so that the frame after
  // an operation costs no more than any other. A replay welds at its first still frame, as it always did.
  if (!scripted()) shown_->renderer().surface_cache().set_whole_weld_delay(SurfaceCache::kPauseWeldDelay);
  if (!options.record.empty()) recorder_.emplace();
  if (options.file.empty()) {
    open_sample(kDefaultSample);
    if (options.up_axis >= 0) view_.up_axis = options.up_axis;
  } else {
    if (options.up_axis >= 0)  // kept for the file, under the name the document gives it
      view_.up_axes[std::filesystem::absolute(options.file).lexically_normal().string()] = options.up_axis;
    std::string remarks;
    if (const std::optional<Error> e = try_open(options.file, options.import.repair, remarks)) {
      // No mesh to keep yet: the default sample shows under the error, and the repair dialog where the
      // repair mends the file. A run that must write a screenshot or save of the file stops (exit 1).
      RepairFindings findings;
      if (!options.import.repair) findings = repair_findings(options.file, options.import);
      if (!findings.offered() && (!options.screenshot.empty() || !options.save.empty())) throw *e;
      open_sample(kDefaultSample);
      file_not_opened_ = *e;
      set_status(e->what(), true);
      if (findings.offered()) repair_prompt_.open(options.file, std::move(findings), e->what());
    } else {
      if (!remarks.empty()) set_status("opened " + document_.source_path() + remarks, false);
      if (!options.import.repair) offer_repair_of_opened(options.file);
    }
  }
}

EditorApp::~EditorApp() {
  target_layer_.reset();
  shown_.reset();
  timer_.reset();
  viewport_.reset();
  ImGui_ImplOpenGL3_Shutdown();
  ImGui::DestroyContext();
}

int EditorApp::run() {
  while (!quit_) {
    frame();
    if (script_finished()) break;
  }
  if (recorder_) recorder_->save(options_.record);
  remember_target_points();  // under the name a save gave the document
  if (const std::string error = save_settings(config_folder_, view_, reach_options_); !error.empty())
    set_status(error, true);
  if (!options_.stats.empty()) write_statistics(options_.stats);
  return 0;
}

bool EditorApp::scripted() const { return script_ || !options_.screenshot.empty() || !options_.save.empty(); }

bool EditorApp::script_finished() {
  if (!scripted() || (script_ && !script_->done()) || mesh_jobs_.running() || layout_frames_ > 0) return false;
  if (view_.target.shown && target_layer_->points().busy()) return false;  // the target's distances as they settle
  // Two more frames after the last event: auto-sized ImGui windows settle on their second frame.
  if (++finishing_frames_ < 3) return false;
  if (file_not_opened_ && !options_.save.empty()) throw *file_not_opened_;  // not the sample in its place
  if (tool_ && !options_.save.empty()) {
    // A replay that ends inside a tool saves what was confirmed: the tool is cancelled, as by Esc.
    InputEvent escape;
    escape.type = InputEvent::Type::key_press;
    escape.key = GLFW_KEY_ESCAPE;
    modal_event(escape);
    tool_.reset();
    set_status("the events ended inside a tool: cancelled before saving", false);
  }
  if (!options_.save.empty()) save_to(options_.save);
  return true;
}

void EditorApp::frame() {
  glfwPollEvents();
  const int swap_interval = view_.vsync && !script_ ? 1 : 0;  // replays run as fast as they can
  if (swap_interval != swap_interval_) glfwSwapInterval(swap_interval_ = swap_interval);
  frame_input_time_ = Clock::now();
  // A replay waits for a background job (simplify, fit), so that it does not depend on its speed.
  // The first frames lay the panels out (the first view is framed beside them) and take no input.
  const bool layout = layout_frames_ > 0;
  const std::vector<InputEvent> events = layout || (script_ && mesh_jobs_.running()) ? std::vector<InputEvent>{}
                                         : script_                                   ? script_->next_frame()
                                                                                     : queue_.take_frame();
  if (recorder_ && !layout) recorder_->record_frame(events);
  for (const InputEvent& e : events) input_.apply(e);

  ImGuiIO& io = ImGui::GetIO();
  int width = 0, height = 0, fb_width = 0, fb_height = 0;
  glfwGetWindowSize(window_.window(), &width, &height);
  window_.framebuffer_size(fb_width, fb_height);
  io.DisplaySize = ImVec2(float(width), float(height));
  if (width > 0 && height > 0)
    io.DisplayFramebufferScale = ImVec2(float(fb_width) / float(width), float(fb_height) / float(height));
  io.DeltaTime =
      script_ ? 1.0f / 60.0f
              : std::clamp(std::chrono::duration<float>(frame_input_time_ - last_frame_time_).count(), 1e-4f, 1.0f);
  last_frame_time_ = frame_input_time_;
  feed_imgui(io, input_, events);
  ImGui_ImplOpenGL3_NewFrame();
  ImGui::NewFrame();

  for (const InputEvent& e : events) handle_event(e);
  follow_cursor();
  draw_ui();
  deselect_hidden();  // a menu's selection
  ImGui::Render();
  render_and_present();
  // A frame without input makes the last operation's undo step, which its own frame left waiting.
  if (events.empty()) document_.settle_history();
}

void EditorApp::render_and_present() {
  int fb_width = 0, fb_height = 0;
  window_.framebuffer_size(fb_width, fb_height);
  // The edit path: only the changed vertices' 9D values and the stencil rows reading them.
  const std::vector<int> changed = document_.take_changed();
  const bool edited = !changed.empty();
  if (edited) {
    show_edit(changed);
  }
  update_target_points();
  if (fb_width > 0 && fb_height > 0) {
    DrawOptions draw = view_.draw;
    if (draw.ellipsoids && !all_ellipsoids(EllipsoidScope(view_.ellipsoid_scope), document_.mesh().n_vertices())) {
      shown_ellipsoids_ = hidden_.elements().shown(selection_neighbourhood(document_.mesh(), selection_.vertices()));
      draw.ellipsoid_vertices = &shown_ellipsoids_;
    } else if (draw.ellipsoids && !hidden_.elements().empty()) {
      shown_ellipsoids_.clear();
      for (size_t v = 0; v < document_.mesh().n_vertices(); ++v)
        if (!hidden_.elements().vertex_hidden(int(v))) shown_ellipsoids_.push_back(int(v));
      draw.ellipsoid_vertices = &shown_ellipsoids_;
    }
    if (const std::string refusal = hidden_.follow(document_.mesh(), *shown_); !refusal.empty())
      set_status("hide: " + refusal, true);
    if (!hidden_.patches().empty()) draw.hidden_patches = &hidden_.patches();
    if (!hidden_.cage_edges().empty()) draw.hidden_edges = &hidden_.cage_edges();
    // Once the surface has settled after an edit or a new mesh, a frame the float evaluation could
    // not represent is said, not just shown.
    if (const long long bad =
            viewport_->draw(*shown_, *target_layer_, camera_, draw, view_.target, fb_width, fb_height, !edited);
        bad > 0)
      set_status(
          document_.display_name() + ": the GPU's evaluation is not finite at " + std::to_string(bad) + " pixels",
          true);
    window_.blit(*viewport_->target());
  }
  window_.bind_default_framebuffer();
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
    window_.wait_for_gpu();
    clock_.edit_shown(frame_input_time_);
  }
  clock_.frame_done();
}

void EditorApp::write_statistics(const std::string& path) {
  const DrawStatistics draw = shown_->renderer().last_statistics();
  nlohmann::json passes = nlohmann::json::object();
  for (const auto& [pass, ms] : timer_->latest()) passes[pass] = ms;
  nlohmann::json j = {{"mesh", opened_name_},
                      {"faces", document_.mesh().n_faces()},
                      {"patches", draw.patches},
                      {"triangles", draw.triangles},
                      {"gl", window_.description()},
                      {"median_frame_ms", clock_.median_frame_ms()},
                      {"median_edit_to_frame_ms", clock_.median_edit_ms()},
                      {"edits", clock_.edit_count()},
                      {"kept_frames", viewport_->kept_frames()},
                      {"last_edit_vertices", last_edit_vertices_},
                      {"gpu_pass_ms", passes},
                      {"free_region", {free_min_.x, free_min_.y, free_max_.x, free_max_.y}},
                      {"unsaved", document_.dirty()}};
  if (!options_.save.empty()) j["saved"] = options_.save;
  for (const char* name : {"Inspector", "View"})  // where the panels were last drawn: x, y, width, height
    if (const ImGuiWindow* panel = ImGui::FindWindowByName(name); panel && panel->Active)
      j["panels"][name] = {panel->Pos.x, panel->Pos.y, panel->Size.x, panel->Size.y};
  write_file_atomically(path, [&j](std::ostream& out) { out << j.dump(2) << "\n"; });
}

void EditorApp::write_screenshot(const std::string& path) {
  try {
    write_image(path, window_.read_pixels());
    set_status("screenshot written to " + path, false);
  } catch (const Error& e) {
    if (!options_.screenshot.empty()) throw;
    set_status(e.what(), true);
  }
}

void EditorApp::draw_ui() {
  commands_.draw_menu_bar();
  draw_handles_and_box();
  draw_modelling_overlay();
  draw_adjust_last_panel();
  draw_job_dialog();
  if (view_.show_inspector) inspector_.draw(document_, selection_, reach_options_, &view_.show_inspector);
  if (const auto request = inspector_.take_sharpness_request()) apply_sharpness(request->corners, request->sharpness);
  if (view_.show_view) {
    const ViewPanelChanges c = draw_view_panel(view_, &view_.show_view);
    if (c.depth) try {
        show_mesh(document_.mesh(), view_.plans());
      } catch (const Error& e) {  // too big for the GPU's buffers: the previous plans stay
        set_status(e.what(), true);
      }
    if (c.matcap) shown_->renderer().set_matcap(load_matcap(view_.matcap));
    if (c.target_shown) remember_target_points();
    if (c.up_axis) {
      if (!document_.source_path().empty()) view_.up_axes[document_.source_path()] = view_.up_axis;
      frame_first_view();
    }
    if (c.load_matcap) {
      browser_purpose_ = BrowserPurpose::load_matcap;
      browser_.open(FileBrowser::Mode::open, "Load MatCap", std::filesystem::current_path().string(), kImageExtensions);
    }
  }
  if (view_.show_statistics) {
    std::vector<ScreenBox> keep_clear;
    if (gizmo_box_) keep_clear.push_back(*gizmo_box_);
    draw_statistics_overlay(clock_, timer_->latest(), shown_->renderer().last_statistics(), {free_min_, free_max_},
                            keep_clear, &view_.show_statistics);
  }
  draw_help_overlay(&view_.show_help, commands_.key_bindings());
  draw_unsaved_prompt();
  draw_repair_prompt();
  handle_browser_result();
  draw_status_bar(document_, selection_summary(selection_, document_.mesh(), select_mode_, select_through_), status_,
                  status_error_);
  note_free_region();
  if (layout_frames_ > 0) {
    --layout_frames_;
    frame_first_view();
  }
  update_title();
}

// The part of the window that the menu bar, the status bar and the panels docked at the right
// edge leave free: where framing puts the selection.
void EditorApp::note_free_region() {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  free_min_ = glm::vec2(vp->WorkPos.x, vp->WorkPos.y);
  free_max_ =
      glm::vec2(vp->WorkPos.x + vp->WorkSize.x, vp->WorkPos.y + vp->WorkSize.y - ImGui::GetFrameHeight() - 4.0f);
  for (const char* name : {"Inspector", "View"}) {
    const ImGuiWindow* panel = ImGui::FindWindowByName(name);
    if (!panel || !panel->Active || panel->Collapsed) continue;
    if (panel->Pos.x + 0.5f * panel->Size.x < vp->WorkPos.x + 0.5f * vp->WorkSize.x) continue;  // not on the right side
    free_max_.x = std::min(free_max_.x, panel->Pos.x - 8.0f);
  }
  free_max_ = glm::max(free_max_, free_min_ + glm::vec2(64.0f));
}

void EditorApp::set_status(const std::string& message, bool error) {
  status_ = message;
  status_error_ = error;
  (error ? std::cerr : std::cout) << "gpsurf-editor: " << message << std::endl;
}

void EditorApp::update_title() {
  const std::string title = "gpsurf - " + document_.display_name() + (document_.dirty() ? " *" : "");
  if (title != last_title_) glfwSetWindowTitle(window_.window(), title.c_str());
  last_title_ = title;
}

int run_editor(const EditorOptions& options) {
  EditorApp editor(options);
  return editor.run();
}

}  // namespace gps
