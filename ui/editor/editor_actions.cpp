// The editor's actions on the document: open, save, undo and redo, the unsaved-changes prompt, and the
// result of File → Simplify… or Fit to… applied as one undo step.
#include <imgui.h>

#include <filesystem>
#include <optional>

#include "core/io/mesh_io.h"
#include "core/mesh/element_names.h"
#include "core/support/error.h"
#include "core/modelling/samples.h"
#include "render/image/matcap_file.h"
#include "ui/editor/editor_app.h"

namespace gps {

namespace {
constexpr size_t kMaxFacesWithLines = 5000;  // larger meshes open with the base-mesh lines off
const std::vector<std::string> kMeshExtensions = {".ply", ".obj", ".off", ".stl"};
}  // namespace

void EditorApp::request(Action action) {
  if (document_.dirty() && action.kind != Action::Kind::none) {
    pending_ = std::move(action);
    prompt_unsaved_ = true;
    return;
  }
  perform(action);
}

void EditorApp::perform(const Action& action) {
  switch (action.kind) {
    case Action::Kind::quit:
      quit_ = true;
      break;
    case Action::Kind::open_file:
      if (!action.argument.empty()) {
        open_file(action.argument);
      } else {  // ask for the file, beside the current one
        browser_purpose_ = BrowserPurpose::open_mesh;
        const std::filesystem::path source = document_.source_path();
        browser_.open(FileBrowser::Mode::open, "Open mesh",
                      source.empty() ? std::filesystem::current_path().string() : source.parent_path().string(),
                      kMeshExtensions);
      }
      break;
    case Action::Kind::open_sample:
      open_sample(action.argument);
      break;
    case Action::Kind::none:
      break;
  }
  pending_ = {};
}

std::optional<Error> EditorApp::try_open(const std::string& path, bool repair, std::string& remarks) {
  const EditorDocument previous = document_;
  ImportOptions options = options_.import;
  options.repair = repair;
  RepairReport report;
  std::vector<std::string> notes;
  try {
    document_.open(path, options, &report, &notes);
    mesh_replaced();          // the renderer may refuse the mesh (valence, GPU limits): nothing changed then
  } catch (const Error& e) {  // the current mesh stays
    document_ = previous;
    return e;
  }
  if (!script_) recent_.add(document_.source_path());
  file_not_opened_.reset();
  remarks.clear();
  if (repair) {
    std::string steps;
    for (const std::string& line : report.lines()) steps += (steps.empty() ? "" : "; ") + line;
    remarks = " repaired (unsaved): " + (steps.empty() ? "nothing to repair" : steps);
  }
  for (const std::string& note : notes) remarks += "; note: " + note;
  return std::nullopt;
}

void EditorApp::report_unopened(const std::string& path, const Error& e) {
  set_status(e.what(), true);
  // What the repair mends (every class, the refused ones first): the user is shown it and asked.
  if (RepairFindings findings = repair_findings(path, options_.import); findings.offered())
    repair_prompt_.open(path, std::move(findings), e.what());
}

void EditorApp::open_file(const std::string& path) {
  std::string remarks;
  if (const std::optional<Error> e = try_open(path, false, remarks)) {
    report_unopened(path, *e);
    return;
  }
  set_status("opened " + document_.source_path() + remarks, false);
  offer_repair_of_opened(path);
}

void EditorApp::offer_repair_of_opened(const std::string& path) {
  // Opened as read, but torn apart by coincident vertices or spoilt by zero-area faces: asked too.
  if (RepairFindings findings = repair_findings(path, options_.import); findings.offered())
    repair_prompt_.open(path, std::move(findings), "", true);
}

void EditorApp::open_repaired(const std::string& path) {
  std::string remarks;
  if (const std::optional<Error> e = try_open(path, true, remarks))
    set_status(e->what(), true);
  else
    set_status("opened " + document_.source_path() + remarks, false);
}

void EditorApp::draw_repair_prompt() {
  switch (repair_prompt_.draw()) {
    case RepairPrompt::Answer::repair:
      open_repaired(repair_prompt_.path());
      break;
    case RepairPrompt::Answer::cancel:
      set_status(repair_prompt_.opened() ? "kept " + repair_prompt_.path() + " as read, unrepaired"
                                         : "not opened " + repair_prompt_.path() + "; kept " + document_.display_name(),
                 false);
      break;
    case RepairPrompt::Answer::none:
      break;
  }
}

void EditorApp::open_sample(const std::string& name) {
  document_.open_sample(name);
  mesh_replaced();
  file_not_opened_.reset();
  set_status("opened the built-in sample '" + name + "': " + sample_description(name), false);
}

void EditorApp::mesh_replaced() {
  ViewOptions view = view_;
  view.triangle_mesh = scheme_for(document_.mesh().topology(), PlanOptions{}) == Scheme::loop;
  const auto mirror = view_.mirror_modifiers.find(document_.source_path());
  shown_->set_mirror_settings(mirror != view_.mirror_modifiers.end() ? mirror->second : MirrorSettings{});
  try {  // first: it throws before anything changes
    show_mesh(document_.mesh(), view.plans());
  } catch (const ElementError& e) {  // the plans name an element as the file read unchanged numbers it
    const bool as_read = !document_.dirty() && !document_.source_path().empty();
    throw Error(document_.display_name() + ": " +
                    e.named(as_read ? file_element_names(document_.source_path()) : ElementNames{}),
                e.kind());
  } catch (const Error& e) {  // the plans' and the GPU's refusals name no file
    throw Error(document_.display_name() + ": " + e.what(), e.kind());
  }
  view_.triangle_mesh = view.triangle_mesh;
  mode_ = Mode::none;
  tool_.reset();  // a tool's edit is of the mesh replaced
  selection_.clear();
  hidden_.elements().clear();
  refresh_hidden();
  const auto kept = view_.up_axes.find(document_.source_path());
  view_.up_axis = kept != view_.up_axes.end() ? kept->second : 1;
  frame_first_view();
  // Base-mesh lines are drawn over the surface: on a dense mesh they would hide it.
  view_.draw.mesh_lines = document_.mesh().n_faces() <= kMaxFacesWithLines;
  reach_options_.radius = 0.1 * bounding_box_diagonal(document_.mesh());
  reach_options_.mirror_tolerance = 1e-6 * bounding_box_diagonal(document_.mesh());
  opened_name_ = document_.display_name();
  reopen_target_points();
}

bool EditorApp::save() {
  if (!document_.can_save_in_place()) {
    save_to("");
    return false;
  }
  save_to(document_.ply_path());
  return !document_.dirty();
}

void EditorApp::save_to(const std::string& path) {
  if (path.empty()) {  // Save As: ask for a name, beside the current file
    browser_purpose_ = BrowserPurpose::save_mesh;
    const std::filesystem::path source = document_.source_path();
    const std::string folder =
        source.empty() ? std::filesystem::current_path().string() : source.parent_path().string();
    const std::string name = source.empty() ? "untitled.ply" : source.stem().string() + ".ply";
    browser_.open(FileBrowser::Mode::save, "Save covariance mesh", folder, {".ply", ".obj"}, name);
    return;
  }
  try {
    document_.save(path);
    remember_mirror();  // under the file's new name too
    if (!script_) recent_.add(document_.source_path());
    set_status("saved " + path, false);
  } catch (const Error& e) {
    if (!options_.save.empty() && path == options_.save) throw;  // a scripted save must not fail quietly
    set_status(e.what(), true);
  }
}

void EditorApp::undo_redo(bool undo) {
  if (modal_active()) return;  // not in the middle of a drag or a tool
  // A modelling step replaced the whole mesh: the GPU rebuilds for it, the camera stays.
  if (const auto selection = undo ? document_.undo() : document_.redo()) rebuild_after_undo(*selection);
}

void EditorApp::draw_unsaved_prompt() {
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

void EditorApp::handle_browser_result() {
  const bool was_open = browser_.is_open();
  const std::optional<std::string> chosen = browser_.draw();
  if (!chosen) {
    if (was_open && !browser_.is_open()) after_save_perform_ = false, pending_ = {};  // cancelled
    return;
  }
  switch (browser_purpose_) {
    case BrowserPurpose::open_mesh:
      open_file(*chosen);
      break;
    case BrowserPurpose::save_mesh:
      save_to(*chosen);
      if (after_save_perform_ && !document_.dirty()) perform(pending_);
      break;
    case BrowserPurpose::load_target:
      show_target_points(*chosen);
      break;
    case BrowserPurpose::load_matcap:
      try {
        shown_->renderer().set_matcap(load_matcap(*chosen));
        view_.matcap = std::filesystem::path(*chosen).filename().string();
      } catch (const Error& e) {
        set_status(e.what(), true);
      }
      break;
  }
  after_save_perform_ = false;
}

void EditorApp::draw_job_dialog() {
  std::optional<MeshJobs::Applied> applied = mesh_jobs_.draw();
  if (!applied) return;
  try {
    install(applied->made);
    operation_note(last_summary_, false);
    if (applied->fit_target) show_target_points(*applied->fit_target);  // how far the fit came, point by point
  } catch (const Error& e) {
    operation_note(e.what(), true);
  }
}

}  // namespace gps
