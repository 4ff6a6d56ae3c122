#include "bench/edit_scene.h"

#include <glad/gl.h>

#include <chrono>

#include "core/modelling/samples.h"

namespace gps {

EditScene::EditScene(const std::string& name, int faces, const PlanOptions& options) : mesh_(make_sample(name, faces)) {
  const auto start = std::chrono::steady_clock::now();
  renderer_.set_mesh(mesh_, options);
  glFinish();
  set_mesh_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  camera_ = frame_mesh(mesh_);
  draw_options_.pixels = 6.0f;
}

void EditScene::frame() {
  renderer_.draw(target_, camera_, draw_options_);
  glFinish();
}

void EditScene::edit(const std::vector<int>& vertices) {
  const double scale = grow_ ? 1.1 : 1.0 / 1.1;
  grow_ = !grow_;
  for (const int v : vertices) mesh_.set_covariance(size_t(v), mesh_.covariance(size_t(v)) * scale);
  renderer_.update_vertices(mesh_, vertices);
}

std::vector<int> EditScene::middle_vertices(int count) const {
  std::vector<int> out(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) out[size_t(i)] = int(mesh_.n_vertices() / 2) + i;
  return out;
}

}  // namespace gps
