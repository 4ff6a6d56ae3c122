#include "bench/edit_figures.h"

#include <glad/gl.h>

#include "bench/edit_scene.h"
#include "bench/median_timing.h"

namespace gps {

nlohmann::json edit_figures(const std::string& name, int faces, const PlanOptions& options) {
  EditScene scene(name, faces, options);
  SurfaceRenderer& renderer = scene.renderer();
  renderer.set_collect_statistics(true);
  scene.frame();  // warm-up, and the triangle count (glFinish made the queries' results available)
  const DrawStatistics statistics = renderer.last_statistics();
  renderer.set_collect_statistics(false);
  const std::vector<int> one = scene.middle_vertices(1), sixteen = scene.middle_vertices(16);
  const std::vector<double> t = interleaved_median_seconds({[&] { scene.frame(); },
                                                            [&] {
                                                              scene.edit(one);
                                                              scene.frame();
                                                            },
                                                            [&] {
                                                              scene.edit(sixteen);
                                                              scene.frame();
                                                            },
                                                            [&] {
                                                              renderer.recompute_all();
                                                              scene.frame();
                                                            },
                                                            [&] {
                                                              scene.edit(one);
                                                              glFinish();
                                                            },
                                                            [&] {
                                                              renderer.recompute_all();
                                                              glFinish();
                                                            }},
                                                           20.0);
  return {{"mesh", name + "/" + std::to_string(faces)},
          {"faces", scene.mesh().n_faces()},
          {"vertices", scene.mesh().n_vertices()},
          {"patches", statistics.patches},
          {"depth", renderer.tables().plans.max_depth},
          {"triangles", statistics.triangles},
          {"frame_ms", t[0] * 1e3},
          {"edit_to_frame_1_vertex_ms", t[1] * 1e3},
          {"edit_to_frame_16_vertices_ms", t[2] * 1e3},
          {"full_recompute_frame_ms", t[3] * 1e3},
          {"edit_1_vertex_compute_ms", t[4] * 1e3},
          {"full_recompute_ms", t[5] * 1e3},
          {"set_mesh_ms", scene.set_mesh_seconds() * 1e3}};
}

}  // namespace gps
