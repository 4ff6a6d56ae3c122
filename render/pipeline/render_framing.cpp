#include "render/pipeline/render_framing.h"

#include <algorithm>
#include <cmath>

#include "render/pipeline/surface_renderer.h"
#include "view/silhouette_framing.h"

namespace gps {

namespace {
glm::dvec3 as_dvec3(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

// Patches captured at a time, and the level for a mesh of n patches: finer for the few large patches
// of a small mesh (whose silhouette bulges between corners), the corners alone past 16,384 patches.
constexpr int kPatchesPerCapture = 8192;
float framing_level(int n_patches) { return n_patches <= 4096 ? 4.0f : n_patches <= 16384 ? 2.0f : 1.0f; }
}  // namespace

std::vector<glm::dvec3> framing_points(SurfaceRenderer& renderer, const CovarianceMesh& mesh, const DrawOptions& o) {
  std::vector<glm::dvec3> points;
  DrawOptions uniform;
  const int n_patches = renderer.tables().plans.n_patches();
  uniform.level = framing_level(n_patches);
  uniform.pixels = 0.0f;
  const Camera any = frame_mesh(mesh);  // uniform levels do not depend on the camera
  for (int first = 0; first < n_patches; first += kPatchesPerCapture)
    for (const TessellatedVertex& v : renderer.capture_vertices(any, uniform, 64, 64, first, kPatchesPerCapture))
      points.emplace_back(v.position[0], v.position[1], v.position[2]);
  if (o.mesh_lines)
    for (size_t i = 0; i < mesh.n_vertices(); ++i) points.push_back(as_dvec3(mesh.mean(i)));
  if (o.ellipsoids)
    for (size_t i = 0; i < mesh.n_vertices(); ++i) {
      const Mat3& s = mesh.covariance(i);
      const glm::dvec3 m = as_dvec3(mesh.mean(i));
      // The ellipsoid's box: along axis k it reaches k-sigma · √Σkk from the mean.
      const glm::dvec3 reach =
          double(o.sigma_scale) * glm::dvec3(std::sqrt(std::max(0.0, s(0, 0))), std::sqrt(std::max(0.0, s(1, 1))),
                                             std::sqrt(std::max(0.0, s(2, 2))));
      for (int c = 0; c < 8; ++c)
        points.push_back(
            m + glm::dvec3(c & 1 ? reach.x : -reach.x, c & 2 ? reach.y : -reach.y, c & 4 ? reach.z : -reach.z));
    }
  return points;
}

Camera render_camera(SurfaceRenderer& renderer, const CovarianceMesh& mesh,
                     const std::vector<float>& yaw_pitch_distance, int up_axis, const DrawOptions& o, int width,
                     int height) {
  Camera camera =
      yaw_pitch_distance.size() < 2 ? frame_mesh(mesh) : frame_mesh(mesh, yaw_pitch_distance[0], yaw_pitch_distance[1]);
  camera.up_axis = up_axis;
  camera = frame_silhouette(camera, framing_points(renderer, mesh, o), double(width) / double(std::max(1, height)));
  if (yaw_pitch_distance.size() > 2) camera.distance = yaw_pitch_distance[2];
  return camera;
}

}  // namespace gps
