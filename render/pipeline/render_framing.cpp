#include "render/pipeline/render_framing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/support/error.h"
#include "render/pipeline/surface_renderer.h"
#include "view/silhouette_framing.h"

namespace gps {

namespace {
// Patches captured at a time, and the level for a mesh of n patches: finer for the few large patches
// of a small mesh (whose silhouette bulges between corners); past 16,384 patches the corners alone,
// which the compute passes evaluated already.
constexpr int kPatchesPerCapture = 8192;
constexpr int kCornersOnlyPatches = 16384;
float framing_level(int n_patches) { return n_patches <= 4096 ? 4.0f : 2.0f; }
// Under perspective the surface nearest the eye is magnified: between the uniform samples it may
// bulge far past them in the image. So the framed view is tessellated again, adaptively at this edge
// length in pixels, and framed on those vertices too, until they fit (at most this many rounds).
constexpr float kViewedFramingPixels = 2.0f;
constexpr int kViewedFramingRounds = 4;
// Only where the framed view brings a point nearer than this share of its distance: an ordinary view
// is not tessellated twice.
constexpr double kMagnifyingDepth = 0.5;
// How far into the margin (of 5 %) those vertices may reach before the view is framed again, in
// normalised device coordinates.
constexpr double kViewedFit = 0.97;

// Whether some of `points` lie so much nearer the eye than the target that perspective magnifies
// them past what samples between them show: nearer than half the distance.
bool magnifies_nearest(const Camera& camera, const std::vector<glm::dvec3>& points) {
  const glm::dvec3 eye = camera.eye_double(), forward = glm::normalize(camera.target - eye);
  return std::any_of(points.begin(), points.end(), [&](const glm::dvec3& p) {
    return glm::dot(p - eye, forward) < kMagnifyingDepth * double(camera.distance);
  });
}

// The captured vertices' positions appended to `points`, those the float evaluation could not
// represent left out: they frame nothing (the draw refuses their pixels).
void append_finite_positions(const std::vector<TessellatedVertex>& vertices, std::vector<glm::dvec3>& points) {
  for (const TessellatedVertex& v : vertices)
    if (std::isfinite(v.position[0] + v.position[1] + v.position[2]))
      points.emplace_back(v.position[0], v.position[1], v.position[2]);
}

glm::dvec3 in_frame(const NormalisedFrame& frame, const Vec3& world) {
  return frame.to_frame(glm::dvec3(world.x(), world.y(), world.z()));
}

// The renderer's frame with its axes along the world's: what the camera is framed in.
NormalisedFrame upright(const NormalisedFrame& frame) {
  NormalisedFrame f = frame;
  f.rotation = glm::dmat3(1.0);
  return f;
}

// Points in the renderer's frame, in its upright frame.
void make_upright(const NormalisedFrame& frame, std::vector<glm::dvec3>& points) {
  if (frame.turned())
    for (glm::dvec3& p : points) p = frame.rotation * p;
}
}  // namespace

std::vector<glm::dvec3> framing_points(SurfaceRenderer& renderer, const CovarianceMesh& mesh, const DrawOptions& o) {
  const NormalisedFrame frame = upright(renderer.frame());
  const int n_patches = renderer.tables().plans.n_patches();
  std::vector<glm::dvec3> points;
  if (n_patches > kCornersOnlyPatches) {
    points = renderer.corner_limit_points();
    // A point the float evaluation could not represent frames nothing (the draw refuses its pixels).
    std::erase_if(points, [](const glm::dvec3& p) { return !std::isfinite(p.x + p.y + p.z); });
  } else {
    DrawOptions uniform;
    uniform.level = framing_level(n_patches);
    uniform.pixels = 0.0f;
    const Camera any;  // uniform levels do not depend on the camera
    for (int first = 0; first < n_patches; first += kPatchesPerCapture)
      append_finite_positions(renderer.capture_frame_vertices(any, uniform, 64, 64, first, kPatchesPerCapture),
                              points);
  }
  make_upright(renderer.frame(), points);
  if (o.mesh_lines)
    for (size_t i = 0; i < mesh.n_vertices(); ++i) points.push_back(in_frame(frame, mesh.mean(i)));
  if (o.ellipsoids)
    for (size_t i = 0; i < mesh.n_vertices(); ++i) {
      const Mat3& s = mesh.covariance(i);
      const glm::dvec3 m = in_frame(frame, mesh.mean(i));
      // The ellipsoid's box: along axis k it reaches k-sigma · √Σkk from the mean.
      const glm::dvec3 reach = double(o.sigma_scale) / frame.unit *
                               glm::dvec3(std::sqrt(std::max(0.0, s(0, 0))), std::sqrt(std::max(0.0, s(1, 1))),
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
  // Framed in the renderer's frame (upright), where the mesh's box is centred and of unit diagonal,
  // then mapped to the world: the same picture wherever the mesh lies and at any scale.
  const NormalisedFrame frame = upright(renderer.frame());
  Vec3 lo, hi;
  bounding_box(mesh, lo, hi);
  // The camera's distance and clipping planes are floats (view/camera.h), as the GPU takes them.
  if (const double across = (hi - lo).norm(); across > 0 && (across < 1e-30 || across > 1e30)) {
    char shown[32];
    std::snprintf(shown, sizeof shown, "%.3g", across);
    throw Error(std::string("the mesh spans ") + shown +
                ", beyond the sizes a view frames (1e-30 to 1e30 across: its camera is in float); scale it first");
  }
  const glm::dvec3 frame_lo = in_frame(frame, lo), frame_hi = in_frame(frame, hi);
  const Vec3 box_lo(frame_lo.x, frame_lo.y, frame_lo.z), box_hi(frame_hi.x, frame_hi.y, frame_hi.z);
  Camera camera = yaw_pitch_distance.size() < 2
                      ? frame_box(box_lo, box_hi)
                      : frame_box(box_lo, box_hi, yaw_pitch_distance[0], yaw_pitch_distance[1]);
  camera.up_axis = up_axis;
  const double aspect = double(width) / double(std::max(1, height));
  std::vector<glm::dvec3> points = framing_points(renderer, mesh, o);
  const Camera unframed = camera;
  camera = frame_silhouette(unframed, points, aspect);
  const int n_patches = renderer.tables().plans.n_patches();
  if (!camera.orthographic && n_patches <= kCornersOnlyPatches && magnifies_nearest(camera, points)) {
    DrawOptions viewed;
    viewed.pixels = kViewedFramingPixels;
    for (int round = 0; round < kViewedFramingRounds; ++round) {
      std::vector<glm::dvec3> seen;
      append_finite_positions(renderer.capture_frame_vertices(camera, viewed, width, height), seen);
      make_upright(renderer.frame(), seen);
      const NdcRect bounds = projected_bounds(camera, seen, aspect);
      if (glm::all(glm::greaterThanEqual(bounds.lo, glm::dvec2(-kViewedFit))) &&
          glm::all(glm::lessThanEqual(bounds.hi, glm::dvec2(kViewedFit))))
        break;
      points.insert(points.end(), seen.begin(), seen.end());
      camera = frame_silhouette(unframed, points, aspect);
    }
  }
  camera.target = frame.to_world(camera.target);
  camera.distance = float(double(camera.distance) * frame.unit);
  if (yaw_pitch_distance.size() > 2) camera.distance = yaw_pitch_distance[2];
  return camera;
}

}  // namespace gps
