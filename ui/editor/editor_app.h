#pragma once
// The editor's parts and their wiring (private to ui/): the document, what shows it (ui/display/),
// the tool running (ui/tools/), the selection and the commands; its methods in one file per concept:
// editor.cpp (frames, drawing, output), editor_pointer.cpp (clicks, boxes, orbit and pan; a press on
// the gizmo starts its drag), editor_actions.cpp (open, save, undo, the unsaved-changes prompt, a
// Simplify… or Fit to… result applied), editor_commands.cpp (the command table: keys, menus, help),
// editor_select_menu.cpp (the Select menu), editor_hide.cpp (hide and reveal), editor_modelling.cpp
// (the Mesh menu), editor_operations.cpp (an operation's result installed as one undo step),
// editor_modal_tools.cpp (the modal tools started and handed the
// events), editor_adjust_last.cpp (F9), editor_snapping.cpp (snapping and the 3D cursor),
// editor_mirror_modifier.cpp (the mirror modifier) and editor_target_points.cpp (a fit's target as
// points).
#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "render/gl/gpu_pass_timer.h"
#include "render/gl/window_context.h"
#include "render/overlays/selected_elements.h"
#include "render/overlays/vertex_dots.h"
#include "core/support/error.h"
#include "core/plans/surface_replanner.h"
#include "ui/editing/axis_handles.h"
#include "ui/editing/cursor_3d.h"
#include "ui/input/command_table.h"
#include "ui/editing/edit_reach.h"
#include "ui/editor/editor.h"
#include "ui/document/editor_document.h"
#include "ui/input/event_script.h"
#include "ui/panels/file_browser.h"
#include "ui/input/glfw_input.h"
#include "ui/input/input_events.h"
#include "ui/panels/inspector_panel.h"
#include "ui/panels/mesh_jobs.h"
#include "ui/editing/merge_distance.h"
#include "ui/settings/recent_files.h"
#include "ui/panels/repair_prompt.h"
#include "ui/editing/pointer_selection.h"
#include "ui/editing/selection.h"
#include "ui/panels/statistics_overlay.h"
#include "ui/editing/transform_mode.h"
#include "ui/tools/modal_tool.h"
#include "ui/panels/view_options.h"
#include "ui/display/shown_surface.h"
#include "ui/display/target_points_layer.h"
#include "ui/display/hidden_view.h"
#include "ui/display/viewport_frame.h"

namespace gps {

// What a confirmation about unsaved changes holds back.
struct Action {
  enum class Kind { none, quit, open_file, open_sample } kind = Kind::none;
  std::string argument;
};

class EditorApp {
public:
  explicit EditorApp(const EditorOptions& options);
  ~EditorApp();
  EditorApp(const EditorApp&) = delete;
  EditorApp& operator=(const EditorApp&) = delete;
  int run();

private:
  using Clock = std::chrono::steady_clock;

  // Pointer and handle drags (editor_pointer.cpp).
  void handle_event(const InputEvent& e);
  void press(const InputEvent& e);
  void release(const InputEvent& e);
  void follow_cursor();
  int pick(glm::vec2 pixel) const;
  Vec3 gizmo_pivot() const;
  std::optional<HandleFrame> gizmo_frame(const Viewport& v) const;
  bool vertex_before_handle(glm::vec2 pixel, const HandleFrame& gizmo, const Handle& handle) const;
  Viewport viewport() const;
  void draw_handles_and_box();
  /// The selection over the 3D view, drawn on the GPU where ImGui's background list reaches it (a
  /// callback there, between the creases and the gizmo): the selected faces and edges, then a dot on
  /// each selected vertex, as set by draw_handles_and_box.
  void draw_selection() const;
  // Selecting in the vertex, edge and face modes: the Select menu (editor_select_menu.cpp); the
  // pointer's clicks and boxes (ui/editing/pointer_selection.h, from release()) select in pointer_scene.
  void build_selection_commands();
  void set_select_mode(SelectMode mode);
  void draw_similar_items();      // Shift+G: select similar
  void select_sharp_edges();      // adds the edges folded by more than sharp_edge_angle_, in edge mode
  void draw_sharp_edges_items();  // the Select menu's angle field and its item
  PointerScene pointer_scene(const Viewport& v) const;
  // Hide and reveal (editor_hide.cpp).
  void build_hide_commands();
  void hide(bool unselected);  // H; Shift+H: what is not selected
  void reveal();               // Alt+H
  void deselect_hidden();      // after anything that selects: hidden elements are never selected
  void refresh_hidden();       // the masks of picking and the patches and lines the frame leaves out
  // Commands (editor_commands.cpp).
  void build_commands();
  void frame_vertices(const std::vector<int>& vertices);  // none: the whole mesh
  glm::vec2 viewport_size() const;
  void axis_view(float yaw, float pitch);
  // Modelling (editor_modelling.cpp): the Mesh menu; its operations applied (editor_operations.cpp).
  void build_modelling_commands();
  bool run_operation(const std::string& name, const std::function<Modelled(const CovarianceMesh&)>& run,
                     SurfaceReplanner* replanner = nullptr);
  // Throws gps::Error before anything changes. `replanner`: the plans of the document's topology,
  // which re-plans a result of the same topology and other sharpness around the changes only.
  void install(Modelled result, SurfaceReplanner* replanner = nullptr);
  // The selection after a change of topology: `selection`'s vertices; in face mode `faces` where given,
  // else the faces whose corners they all are.
  void topology_changed(const std::vector<int>& selection, const std::vector<int>& faces = {});
  void rebuild_after_undo(const SelectionRecord& selection);
  void operation_note(const std::string& message, bool error);
  // The Inspector's crease or corner field: the selection's sharpness set as one undo step.
  void apply_sharpness(bool corners, double sharpness);
  bool modal_active() const { return tool_ != nullptr; }
  // The modal tools (editor_modal_tools.cpp): one runs at a time and takes the events first.
  ToolContext tool_context();
  void start_tool(const std::function<std::unique_ptr<ModalTool>(ToolContext&)>& make);
  bool modal_event(const InputEvent& e);  // true: the tool took the event
  // run_operation without the check for a running tool (a tool's own operation).
  bool operate(const std::string& name, const std::function<Modelled(const CovarianceMesh&)>& run,
               SurfaceReplanner* replanner);
  void show_preview(std::shared_ptr<const CovarianceMesh> mesh, const std::vector<int>& selected,
                    std::optional<ReplannedTables> surface);
  void show_document(std::optional<ReplannedTables> surface);
  void draw_delete_items();
  void draw_merge_items();
  void draw_add_items();
  void draw_modelling_overlay();
  // Adjust last operation (editor_adjust_last.cpp): F9's panel over the last tool's operation.
  void draw_adjust_last_panel();
  void adjust_last(const std::vector<double>& values);
  // Snapping and the 3D cursor (editor_snapping.cpp).
  void build_snapping_commands();
  void place_cursor(glm::vec2 pixel);                     // on the surface under the pixel, else at the cursor's depth
  std::optional<Vec3> surface_at(glm::vec2 pixel) const;  // read back from the last frame; none: background
  void set_cursor(const Vec3& point, const std::string& how);
  // The mirror modifier (editor_mirror_modifier.cpp): the mesh shown through it, its commands.
  void build_mirror_commands();
  // ShownSurface::show, then the clipping the document's edits keep and the modifier's refusal said.
  // Throws gps::Error as set_mesh does, before anything changes.
  void show_mesh(const CovarianceMesh& mesh, const PlanOptions& plans,
                 std::optional<ReplannedTables> surface = std::nullopt, const std::vector<int>& origin = {});
  void show_edit(const std::vector<int>& changed);  // the document's Gaussians `changed`, on both sides
  void set_mirror(const MirrorSettings& settings);  // shown at once and kept for the file
  void remember_mirror();                           // kept for the document's file (the View settings)
  void apply_mirror();                              // the document replaced by its mirror, one undo step
  void draw_mirror_items();
  // The target points over the surface (editor_target_points.cpp).
  void build_target_point_commands();
  void show_target_points(const std::string& path);
  void reopen_target_points();    // the target kept for the document's file, or none
  void remember_target_points();  // kept for the document's file (the View settings)
  void update_target_points();    // once a frame, before drawing
  // Actions (editor_actions.cpp).
  void request(Action action);
  void perform(const Action& action);
  // Opens a mesh file as the document, repaired where `repair` (with the command line's --weld); where
  // it fails nothing changes and the error is returned, else `remarks` gets what the repair did and the
  // reader's notes, for the status line ("" where there are none).
  std::optional<Error> try_open(const std::string& path, bool repair, std::string& remarks);
  // A file that did not open: the error in the status line and, where the repair mends it, the dialog.
  void report_unopened(const std::string& path, const Error& e);
  // A file that opened as read but holds what the repair mends: the dialog, Cancel keeping it as read.
  void offer_repair_of_opened(const std::string& path);
  void open_file(const std::string& path);
  void open_repaired(const std::string& path);
  void draw_repair_prompt();
  void frame_first_view();  // the default angles at the file's up axis, the mesh framed in the free region
  void open_sample(const std::string& name);
  bool save();  // false: a file name is being asked for
  void save_to(const std::string& path);
  void undo_redo(bool undo);
  void mesh_replaced();
  void draw_unsaved_prompt();
  void handle_browser_result();
  void draw_job_dialog();  // File → Simplify… and Fit to…: the result applied as one undo step
  // Frames and output (editor.cpp).
  void frame();
  void draw_ui();
  void render_and_present();
  bool script_finished();
  // Driven by a replay, or run for a screenshot or a save (not by a user at the window).
  bool scripted() const;
  void write_screenshot(const std::string& path);
  void write_statistics(const std::string& path);
  void set_status(const std::string& message, bool error);
  void update_title();
  void note_free_region();

  EditorOptions options_;
  std::string config_folder_, layout_file_;  // where settings and the panel layout are kept
  WindowContext window_;
  GlfwInputForwarder input_forwarder_;
  // What the window shows of the document, and its renderer. What follows it keeps the revision it
  // last followed: the finite check, the hidden patches and lines, and the target points' layer.
  std::unique_ptr<ShownSurface> shown_;
  std::unique_ptr<GpuPassTimer> timer_;
  std::unique_ptr<ViewportFrame> viewport_;          // the 3D view's target, kept while nothing in it changes
  std::unique_ptr<TargetPointsLayer> target_layer_;  // the dense target shown as points, and their distances
  std::unique_ptr<VertexDots> selection_dots_;       // a dot on each selected vertex, over the 3D view
  std::unique_ptr<SelectedElements> selected_elements_;  // the selected faces and edges, over it
  EditorDocument document_;
  std::string opened_name_;  // the display name of the mesh as opened (a save renames the document)
  Selection selection_;
  Camera camera_;
  ViewOptions view_;
  ReachOptions reach_options_;
  InspectorPanel inspector_;
  FileBrowser browser_;
  enum class BrowserPurpose {
    open_mesh,
    save_mesh,
    load_matcap,
    load_target
  } browser_purpose_ = BrowserPurpose::open_mesh;
  RecentFiles recent_;
  RepairPrompt repair_prompt_;
  FrameClock clock_;
  CommandTable commands_;

  InputQueue queue_;
  InputState input_;
  std::optional<EventScript> script_;
  std::optional<EventRecorder> recorder_;
  int finishing_frames_ = 0;
  // Why the file given on the command line did not open, while the sample shown in its place stays:
  // a run that must save the file ends with it instead of saving the sample.
  std::optional<Error> file_not_opened_;

  enum class Mode { none, click, box, orbit, pan } mode_ = Mode::none;  // a drag of the gizmo is a tool
  int mode_button_ = 0;
  glm::vec2 press_pixel_{0.0f}, last_cursor_{0.0f};
  size_t last_edit_vertices_ = 0;              // the last tool's edit reached (the statistics)
  glm::vec2 free_min_{0.0f}, free_max_{1.0f};  // the part of the window the panels leave free
  int layout_frames_ = 2;               // frames without input that lay the panels out before the first view is framed
  std::optional<ScreenBox> gizmo_box_;  // where the gizmo was drawn this frame (the statistics keep clear of it)
  std::vector<int> shown_ellipsoids_;   // the vertices whose ellipsoids are drawn, when not all
  SelectMode select_mode_ = SelectMode::vertex;
  HiddenView hidden_;               // what is hidden, and what picking and the frame leave out for it
  bool select_through_ = false;     // clicks and boxes take hidden elements too (X-ray)
  double similar_threshold_ = 0.0;  // Select similar's (Blender's default)
  double sharp_edge_angle_ = 30.0;  // degrees: Select sharp edges takes the edges folded by more (Blender's default)
  bool alt_press_ = false;          // the left press had Alt: a click selects a loop, a drag orbits

  // Modelling: the modal tool running (none: nullptr) and the pivot of G / S / R (a tool's preview is
  // the shown surface's).
  std::unique_ptr<ModalTool> tool_;
  TransformPivot transform_pivot_ = TransformPivot::median;
  Cursor3D cursor_;
  // The last operation a tool made that F9 can adjust, while its step is the document's last.
  std::optional<AdjustableOperation> adjustable_;
  bool show_adjust_last_ = false;
  MeshJobs mesh_jobs_;                             // File → Simplify… and Fit to…
  std::string popup_request_;                      // a popup menu (Delete, Merge, Add) a key asked for
  double merge_distance_ = kDefaultMergeDistance;  // the Merge menu's By distance (of the diagonal)
  std::string last_summary_;                       // what the last operation did

  Clock::time_point frame_input_time_{}, last_frame_time_ = Clock::now();
  Action pending_;
  bool prompt_unsaved_ = false, after_save_perform_ = false, quit_ = false;
  std::string screenshot_request_;
  std::string status_;
  bool status_error_ = false;
  std::string last_title_;
  int swap_interval_ = -1;
};

}  // namespace gps
