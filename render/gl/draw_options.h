#pragma once
// What a frame of the surface renderer draws, and the uniforms every surface program reads from it.
#include <glm/glm.hpp>
#include <algorithm>
#include <vector>

#include "view/camera.h"
#include "render/gl/normalised_frame.h"
#include "render/gl/shader_program.h"

namespace gps {

enum class ShadingMode { matcap = 0, normals = 1, flat = 2 };

/// The opacity of the base mesh's lines where the surface hides them (those in front are opaque).
constexpr float kHiddenCageAlpha = 0.25f;

/// What crack checks switch on: never part of a draw a user sees.
struct DrawDiagnostics {
  bool back_faces_magenta = false;      // draw back faces in pure magenta: a crack shows them
  bool mismatched_edge_levels = false;  // give neighbouring patches different edge levels on purpose
  bool operator==(const DrawDiagnostics&) const = default;
};

struct DrawOptions {
  float level = 8.0f;   // uniform tessellation level 1..64
  float pixels = 0.0f;  // > 0: adaptive levels, target edge length in pixels
  ShadingMode mode = ShadingMode::matcap;
  bool wireframe = false;   // tessellation wireframe over the shading
  bool mesh_lines = false;  // the base mesh as thin grey lines, faint (kHiddenCageAlpha) where behind the surface
  bool ellipsoids = false;  // covariance ellipsoids
  const std::vector<int>* ellipsoid_vertices = nullptr;  // set: only these vertices' ellipsoids (ascending)
  float sigma_scale = 1.0f;
  glm::vec3 background{1.0f, 1.0f, 1.0f};
  bool static_triangles = false;  // draw the triangles of set_triangles() instead of the patches
  bool surface_cache = true;      // redraw stored triangles while points and levels stay (render/cache/surface_cache.h)
  // Hidden faces (the editor's H): set, these patches (ascending) are not drawn, and the frame is drawn
  // live (the surface cache stores every patch); the others are drawn exactly as without it.
  const std::vector<int>* hidden_patches = nullptr;
  const std::vector<char>* hidden_edges = nullptr;  // set: the mesh lines leave out the edges marked 1 (by index)
  DrawDiagnostics diagnostics;    // off in every draw a user sees

  /// The same values, the lists the same pointers (DrawnOptions compares what they hold).
  bool operator==(const DrawOptions&) const = default;
};

/// A frame's options with copies of the lists they point to, to tell whether a later frame's are the
/// same: every value equal, each list set or unset alike and holding the same elements. Kept in one
/// place (it points into itself), so neither copied nor moved.
class DrawnOptions {
public:
  DrawnOptions() = default;
  DrawnOptions(const DrawnOptions&) = delete;
  DrawnOptions& operator=(const DrawnOptions&) = delete;

  /// Takes `o`'s values and copies of its lists.
  void record(const DrawOptions& o);
  bool same(const DrawOptions& o) const;

private:
  DrawOptions values_;  // the lists pointing to the copies below
  std::vector<int> ellipsoid_vertices_, hidden_patches_;
  std::vector<char> hidden_edges_;
};

/// The adaptive target edge length of a render when none is given: 4 pixels up to a 400-pixel image,
/// growing with the image's smaller side (1% of it), so that a curve's facets stay about as visible at
/// any output size.
inline float default_adaptive_pixels(int width, int height) {
  return std::max(4.0f, 0.01f * float(std::min(width, height)));
}

/// A render's tessellation: uniform `level` where it is above 0, else adaptive with target edge length
/// `pixels` (default_adaptive_pixels() of the image where 0).
inline void set_render_tessellation(DrawOptions& o, int level, float pixels, int width, int height) {
  o.level = level > 0 ? float(level) : o.level;
  o.pixels = level > 0 ? 0.0f : pixels > 0 ? pixels : default_adaptive_pixels(width, height);
}

/// Whether a frame of `o` leaves patches out.
inline bool hides_patches(const DrawOptions& o) { return o.hidden_patches && !o.hidden_patches->empty(); }

/// The uniform level of `o`, clamped to 1..64.
inline float uniform_level(const DrawOptions& o) { return std::clamp(o.level, 1.0f, 64.0f); }

/// The tessellation levels' uniforms (shaders/tess_levels.glsl).
void set_level_uniforms(const ShaderProgram& p, const glm::mat4& view_projection, glm::vec2 viewport,
                        const DrawOptions& o);
/// Camera, viewport, levels and shading of a frame, for the patch, cached and static-triangle programs.
/// The points drawn lie in `frame` (the identity for world-space data): the view-projection is combined
/// with its map in double, and the position AOV is written in world coordinates.
void set_frame_uniforms(const ShaderProgram& p, const Camera& camera, const DrawOptions& o, float aspect, int width,
                        int height, const NormalisedFrame& frame = {});
/// The camera's view-projection of points in `frame`, combined in double.
glm::mat4 frame_view_projection(const Camera& camera, float aspect, const NormalisedFrame& frame);

}  // namespace gps
