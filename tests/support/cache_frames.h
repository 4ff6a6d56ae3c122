#pragma once
// Frames of a surface renderer read back for the surface cache's tests: a frame's AOVs, drawn with the
// cache on or off, compared pixel by pixel; the stored triangles compared bit for bit; the draw
// options and the vertex moves the tests share; the weld modes they run under.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "core/mesh/covariance_mesh.h"
#include "render/cache/surface_cache.h"
#include "render/gl/render_target.h"
#include "render/pipeline/surface_renderer.h"
#include "view/camera.h"

namespace gps::test {

// Colour, position and normal AOVs of one frame.
struct Frame {
  Image layers[3];
};

inline Frame draw(SurfaceRenderer& renderer, const RenderTarget& target, const Camera& camera, DrawOptions o,
                  bool cache) {
  o.surface_cache = cache;
  renderer.draw(target, camera, o);
  Frame f;
  for (int a = 0; a < 3; ++a) f.layers[a] = target.read(a);
  return f;
}

// Pixels (of any layer) whose floats differ in any bit.
inline size_t differing_pixels(const Frame& a, const Frame& b) {
  size_t count = 0;
  for (int l = 0; l < 3; ++l) {
    const Image &x = a.layers[l], &y = b.layers[l];
    if (x.pixels.size() != y.pixels.size()) return size_t(-1);
    const size_t c = size_t(x.channels);
    for (size_t i = 0; i < x.pixels.size(); i += c)
      count += std::memcmp(&x.pixels[i], &y.pixels[i], c * sizeof(float)) != 0;
  }
  return count;
}

// Moves base vertex v by `fraction` of the mesh's diagonal (a different direction per vertex).
inline void move_vertex(CovarianceMesh& mesh, int v, double fraction) {
  const Vec3 direction = Vec3(1.0 + v % 3, 0.5 - v % 2, 0.25 + v % 5).normalized();
  mesh.set_mean(size_t(v), mesh.mean(size_t(v)) + fraction * bounding_box_diagonal(mesh) * direction);
}

inline DrawOptions uniform(float level) {
  DrawOptions o;
  o.level = level;
  return o;
}

inline DrawOptions adaptive(float pixels) {
  DrawOptions o;
  o.pixels = pixels;
  return o;
}

// The stored triangles of two frames (read back) are the same, bit for bit.
inline ::testing::AssertionResult same_triangles(const TriangleMesh& a, const TriangleMesh& b) {
  if (a.triangles != b.triangles || a.positions.size() != b.positions.size())
    return ::testing::AssertionFailure() << a.triangles.size() << " triangle corners against " << b.triangles.size();
  size_t differing = 0;
  for (size_t i = 0; i < a.positions.size(); ++i)
    differing += a.positions[i] != b.positions[i] || a.normals[i] != b.normals[i];
  if (differing > 0)
    return ::testing::AssertionFailure() << differing << " of " << a.positions.size() << " vertices differ";
  return ::testing::AssertionSuccess();
}

/// The weld modes a cache test runs under: welded at each capture (as on a GPU), by the first frame
/// that draws the stored vertices unchanged (as on llvmpipe), and never; and their test names.
inline const auto kWeldModes =
    ::testing::Values(SurfaceCache::Weld::at_capture, SurfaceCache::Weld::when_settled, SurfaceCache::Weld::off);
inline std::string weld_mode_name(const ::testing::TestParamInfo<SurfaceCache::Weld>& info) {
  return info.param == SurfaceCache::Weld::at_capture     ? "WeldedAtCapture"
         : info.param == SurfaceCache::Weld::when_settled ? "WeldedWhenSettled"
                                                          : "AsCaptured";
}

}  // namespace gps::test
