#pragma once
// A large sample on the GPU in a 1280×720 frame at adaptive 6-pixel edges, with the edits the
// edit-to-frame benchmarks time (`gpsurf bench --edit`, gpsurf_bench_edit). A current GL context needed.
#include <string>
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "render/gl/render_target.h"
#include "render/pipeline/surface_renderer.h"
#include "view/camera.h"

namespace gps {

class EditScene {
public:
  /// Sample `name` at `faces` faces on the GPU (set_mesh is timed: set_mesh_seconds()).
  EditScene(const std::string& name, int faces, const PlanOptions& options);

  /// One frame, to after glFinish.
  void frame();
  /// Scales the covariances of `vertices` by 1.1, the next edit back by 1/1.1 (the surface stays
  /// put), and updates the renderer: the changed vertices' 9D points and the stencil rows that read them.
  void edit(const std::vector<int>& vertices);

  const CovarianceMesh& mesh() const { return mesh_; }
  SurfaceRenderer& renderer() { return renderer_; }
  const Camera& camera() const { return camera_; }
  double set_mesh_seconds() const { return set_mesh_seconds_; }
  /// The middle vertex and the `count` − 1 after it: the vertices an edit of `count` changes.
  std::vector<int> middle_vertices(int count) const;

private:
  CovarianceMesh mesh_;
  SurfaceRenderer renderer_;
  double set_mesh_seconds_ = 0;
  Camera camera_;
  RenderTarget target_{1280, 720};
  DrawOptions draw_options_;
  bool grow_ = true;
};

}  // namespace gps
