#include "ui/document/editor_document.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <utility>

#include "core/io/mesh_io.h"
#include "core/modelling/samples.h"

namespace gps {

namespace {

// Whether a PLY file's header says binary (its first line after "ply" is the format line).
bool is_binary_ply(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string magic, format;
  std::getline(in, magic);
  std::getline(in, format);
  return format.rfind("format binary", 0) == 0;
}

}  // namespace

void EditorDocument::open(const std::string& path, const ImportOptions& options, RepairReport* report,
                          std::vector<std::string>* notes) {
  CovarianceMesh loaded = read_mesh(path, options, report, notes);  // throws before anything changes
  const bool own_ply = extension_of(path) == ".ply";
  const std::string absolute = std::filesystem::absolute(path).lexically_normal().string();
  binary_ = !own_ply || is_binary_ply(path);
  replace(std::move(loaded), absolute, own_ply ? absolute : "", std::filesystem::path(path).filename().string());
  if (options.repair) history_.mark_unsaved();
}

void EditorDocument::open_sample(const std::string& name) {
  CovarianceMesh loaded = make_sample(name);
  binary_ = true;
  replace(std::move(loaded), "", "", "sample " + name);
}

void EditorDocument::save(const std::string& path) {
  const bool ply = extension_of(path) == ".ply";
  write_mesh(path, mesh_, ply && binary_);
  if (!ply) return;  // an OBJ export keeps no covariances: the document stays unsaved
  const std::string absolute = std::filesystem::absolute(path).lexically_normal().string();
  ply_path_ = source_path_ = absolute;
  display_name_ = std::filesystem::path(path).filename().string();
  history_.mark_saved();
}

void EditorDocument::replace(CovarianceMesh loaded, const std::string& source, const std::string& ply_path,
                             const std::string& name) {
  mesh_ = std::move(loaded);
  history_.clear();
  edit_.reset();
  edit_index_.clear();
  changed_.clear();
  source_path_ = source;
  ply_path_ = ply_path;
  display_name_ = name;
}

void EditorDocument::begin_edit() {
  if (edit_) commit_edit();
  edit_.emplace();
  edit_index_.clear();
}

void EditorDocument::touch(int vertex) {
  changed_.push_back(vertex);
  if (!edit_ || edit_index_.count(vertex)) return;
  edit_index_.emplace(vertex, edit_->vertices.size());
  edit_->vertices.push_back(vertex);
  edit_->means_before.push_back(mesh_.mean(size_t(vertex)));
  edit_->covariances_before.push_back(mesh_.covariance(size_t(vertex)));
}

void EditorDocument::set_mean(int vertex, const Vec3& mean) {
  touch(vertex);
  Vec3 kept = mean;
  if (clip_ && std::abs(start_mean(vertex)[clip_->axis]) <= clip_->tolerance) kept[clip_->axis] = 0.0;
  mesh_.set_mean(size_t(vertex), kept);
}

void EditorDocument::set_covariance(int vertex, const Mat3& covariance) {
  touch(vertex);
  mesh_.set_covariance(size_t(vertex), covariance);
}

bool EditorDocument::set_gaussians(const CovarianceMesh& mesh) {
  if (mesh.n_vertices() != mesh_.n_vertices()) return false;
  for (size_t v = 0; v < mesh.n_vertices(); ++v) {
    if (mesh_.mean(v) != mesh.mean(v)) set_mean(int(v), mesh.mean(v));
    if (mesh_.covariance(v) != mesh.covariance(v)) set_covariance(int(v), mesh.covariance(v));
  }
  return true;
}

Vec3 EditorDocument::start_mean(int vertex) const {
  const auto it = edit_ ? edit_index_.find(vertex) : edit_index_.end();
  return it != edit_index_.end() ? edit_->means_before[it->second] : mesh_.mean(size_t(vertex));
}

const Mat3& EditorDocument::start_covariance(int vertex) const {
  const auto it = edit_ ? edit_index_.find(vertex) : edit_index_.end();
  return it != edit_index_.end() ? edit_->covariances_before[it->second] : mesh_.covariance(size_t(vertex));
}

void EditorDocument::revert_edit() {
  if (!edit_) return;
  for (size_t i = 0; i < edit_->vertices.size(); ++i) {
    mesh_.set_mean(size_t(edit_->vertices[i]), edit_->means_before[i]);
    mesh_.set_covariance(size_t(edit_->vertices[i]), edit_->covariances_before[i]);
    changed_.push_back(edit_->vertices[i]);
  }
}

bool EditorDocument::edit_changed(const VertexEdit& edit) const {
  for (size_t i = 0; i < edit.vertices.size(); ++i) {
    const size_t v = size_t(edit.vertices[i]);
    if (mesh_.mean(v) != edit.means_before[i] || mesh_.covariance(v) != edit.covariances_before[i]) return true;
  }
  return false;
}

void EditorDocument::settle_under(const VertexEdit& edit) {
  if (!history_.pending()) return;
  std::vector<Vec3> means;
  std::vector<Mat3> covariances;
  for (size_t i = 0; i < edit.vertices.size(); ++i) {
    const size_t v = size_t(edit.vertices[i]);
    means.push_back(mesh_.mean(v));
    covariances.push_back(mesh_.covariance(v));
    mesh_.set_mean(v, edit.means_before[i]);
    mesh_.set_covariance(v, edit.covariances_before[i]);
  }
  history_.settle(mesh_);
  for (size_t i = 0; i < edit.vertices.size(); ++i) {
    mesh_.set_mean(size_t(edit.vertices[i]), means[i]);
    mesh_.set_covariance(size_t(edit.vertices[i]), covariances[i]);
  }
}

bool EditorDocument::commit_edit() {
  if (!edit_) return false;
  VertexEdit edit = std::move(*edit_);
  edit_.reset();
  edit_index_.clear();
  const bool changed = edit_changed(edit);
  if (changed) {
    settle_under(edit);
    history_.commit(std::move(edit), mesh_);
  }
  return changed;
}

void EditorDocument::settle_history() {
  if (!edit_) history_.settle(mesh_);
}

void EditorDocument::cancel_edit() {
  revert_edit();
  edit_.reset();
  edit_index_.clear();
}

void EditorDocument::apply(Modelled result, const SelectionRecord& selection_before) {
  if (edit_) commit_edit();
  MeshReplacement step;
  step.selection_before = selection_before;
  step.selection_after.vertices = std::move(result.selection);
  PendingReplacement pending{std::move(mesh_), std::move(result.vertex_origin)};
  mesh_ = std::move(result.mesh);
  history_.commit(std::move(step), std::move(pending));
  changed_.clear();  // the vertices are new: the GPU rebuilds
}

bool EditorDocument::commit_edit_into_last_operation(const SelectionRecord& selection) {
  if (edit_ && history_.pending()) {  // the deltas, made later, take the mesh with the edit
    const bool changed = edit_changed(*edit_);
    edit_.reset();
    edit_index_.clear();
    if (changed) history_.fold_into_pending(selection);
    return changed;
  }
  if (!commit_edit()) return false;
  history_.fold_last_into_replacement(mesh_, selection);
  return true;
}

std::optional<SelectionRecord> EditorDocument::undo() {
  if (!can_undo()) return std::nullopt;
  Restored restored = history_.undo(mesh_);
  if (restored.replaced_selection) {
    changed_.clear();
    replaced_origin_ = std::move(restored.origin);
  }
  changed_.insert(changed_.end(), restored.vertices.begin(), restored.vertices.end());
  return restored.replaced_selection;
}

std::optional<SelectionRecord> EditorDocument::redo() {
  if (!can_redo()) return std::nullopt;
  Restored restored = history_.redo(mesh_);
  if (restored.replaced_selection) {
    changed_.clear();
    replaced_origin_ = std::move(restored.origin);
  }
  changed_.insert(changed_.end(), restored.vertices.begin(), restored.vertices.end());
  return restored.replaced_selection;
}

std::optional<SelectionRecord> EditorDocument::discard_last_operation() {
  std::optional<SelectionRecord> selection = undo();
  history_.drop_redo();
  return selection;
}

std::vector<int> EditorDocument::take_changed() {
  std::vector<int> changed;
  changed.swap(changed_);
  std::sort(changed.begin(), changed.end());
  changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
  return changed;
}

}  // namespace gps
