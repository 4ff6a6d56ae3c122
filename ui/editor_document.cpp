#include "ui/editor_document.h"

#include <filesystem>
#include <fstream>

#include "core/mesh_io.h"
#include "core/samples.h"

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

void EditorDocument::open(const std::string& path) {
  CovarianceMesh loaded = read_mesh(path);  // throws before anything changes
  const bool own_ply = extension_of(path) == ".ply";
  const std::string absolute = std::filesystem::absolute(path).lexically_normal().string();
  binary_ = own_ply && is_binary_ply(path);
  replace(std::move(loaded), absolute, own_ply ? absolute : "", std::filesystem::path(path).filename().string());
}

void EditorDocument::open_sample(const std::string& name) {
  CovarianceMesh loaded = make_sample(name);
  binary_ = false;
  replace(std::move(loaded), "", "", "sample " + name);
}

void EditorDocument::save(const std::string& path) {
  const bool ply = extension_of(path) == ".ply";
  write_mesh(path, mesh, ply && binary_);
  if (!ply) return;  // an OBJ export keeps no covariances: the document stays unsaved
  const std::string absolute = std::filesystem::absolute(path).lexically_normal().string();
  ply_path_ = source_path_ = absolute;
  display_name_ = std::filesystem::path(path).filename().string();
  history.mark_saved();
}

void EditorDocument::replace(CovarianceMesh loaded, const std::string& source, const std::string& ply_path, const std::string& name) {
  mesh = std::move(loaded);
  history.clear();
  source_path_ = source;
  ply_path_ = ply_path;
  display_name_ = name;
  ++generation_;
}

}  // namespace gps
