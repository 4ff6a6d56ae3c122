#pragma once
// The patch draw (docs/design.md §2): GL_PATCHES of one vertex each, evaluated by the tessellation
// programs of the plan's patch shape (quads: Catmull-Clark plans, triangles: Loop plans), drawn
// shaded, as wireframe, under transform feedback for tests (TessellatedVertex) or for the surface
// cache, with optional pipeline-statistics queries.
#include <array>
#include <memory>
#include <vector>

#include "core/plans/plan_builder.h"
#include "render/gl/draw_options.h"
#include "render/gl/point_precision.h"
#include "render/gl/gl_object.h"
#include "render/gl/query_ring.h"
#include "render/gl/shader_program.h"
#include "render/gl/shape_programs.h"
#include "render/pipeline/patch_level_bound.h"

namespace gps {

/// One vertex the tessellator produced: patch, (u, v), position and normal (transform feedback).
/// A vertex on a patch edge is evaluated from the canonical patch of that point
/// (shaders/canonical_edge.glsl): `evaluated` is the patch and (u, v) that computed it.
struct TessellatedVertex {
  float patch, u, v;
  float position[3];
  float normal[3];
  float evaluated[3];
  /// Whether the vertex lies on an infinitely sharp crease of its patch (core/plans/patch_adjacency.h):
  /// its normal is then its own patch's at (patch, u, v), its position still the canonical patch's,
  /// and `evaluated` names its edge point instead (shaders/limit_point.glsl, own_crease_normal).
  bool on_crease() const { return evaluated[0] < 0.0f; }
};

/// What the patch draws produced (pipeline-statistics queries; see SurfaceRenderer::set_collect_statistics).
struct DrawStatistics {
  long long triangles = 0;  // primitives the tessellator generated
  long long vertices = 0;   // tessellation evaluation shader invocations, or where `cached` the vertex shader
                            // invocations of the stored vertices drawn; -1 not counted (without
                            // ARB_pipeline_statistics_query, or a frame drawn as the surface cache captured it)
  int patches = 0;          // patches of the plan
  bool cached = false;      // drawn from the surface cache: `triangles` are the stored ones, nothing was evaluated
};

/// What a patch program writes: shaded fragments, TessellatedVertex, shaded with the triangle
/// wireframe (triangle patches: their tessellator's triangles do not follow lines of constant
/// barycentrics, so mesh_geom.glsl draws it), what the surface cache stores (cache_vert.glsl), or
/// shaded fragments and what the cache stores both (a frame that captures as it draws).
enum class PatchOutput { shaded, feedback, wireframe, capture, shaded_capture };

class PatchDraw {
public:
  /// Needs a current GL 4.5 context.
  PatchDraw();
  PatchDraw(const PatchDraw&) = delete;
  PatchDraw& operator=(const PatchDraw&) = delete;

  /// The programs for points of `precision` from now on (each built at its first use; a precision
  /// the driver cannot compile is refused here).
  void set_precision(PointPrecision precision);

  /// Quads have no wireframe program: their fragment shader draws it.
  const ShaderProgram& program(PatchShape shape, PatchOutput output) const;
  /// The program for a frame of `o`.
  const ShaderProgram& frame_program(PatchShape shape, const DrawOptions& o) const {
    return program(shape, shape == PatchShape::triangle && o.wireframe ? PatchOutput::wireframe : PatchOutput::shaded);
  }
  /// Draws patches [first_patch, first_patch + n_patches) of `n_total` (n_patches < 0: to the last)
  /// with `program` (bound, with the plan buffers and its uniforms), a program of `shape`, counted
  /// by the statistics queries if collecting.
  void draw(PatchShape shape, const ShaderProgram& program, const DrawOptions& o, int n_total, int first_patch = 0,
            int n_patches = -1) const;
  /// The triangles the tessellator generates for `o` in a width × height viewport, of those
  /// patches (a draw with rasterisation discarded).
  long long count_triangles(PatchShape shape, const Camera& camera, const DrawOptions& o, int width, int height,
                            int n_total, int first_patch = 0, int n_patches = -1) const;
  /// The vertices the tessellator generates for `o` in a width × height viewport (no
  /// rasterisation) of those patches, positions in world coordinates.
  std::vector<TessellatedVertex> capture_vertices(PatchShape shape, const Camera& camera, const DrawOptions& o,
                                                  int width, int height, int n_total, int first_patch,
                                                  int n_patches) const;
  /// The same with positions in frame() coordinates, as the GPU evaluates them (in float, world
  /// coordinates far from the origin would round away the surface's shape).
  std::vector<TessellatedVertex> capture_frame_vertices(PatchShape shape, const Camera& camera, const DrawOptions& o,
                                                        int width, int height, int n_total, int first_patch,
                                                        int n_patches) const;

  /// The frame the plan points lie in (SurfaceRenderer::set_mesh); count_triangles() and
  /// capture_vertices() draw in it.
  void set_frame(const NormalisedFrame& frame) { frame_ = frame; }
  const NormalisedFrame& frame() const { return frame_; }

  void set_collect_statistics(bool collect);
  /// The counts of the newest draw whose queries finished (triangles, vertices; -1 vertices without
  /// ARB_pipeline_statistics_query), into `s`; unchanged while none finished.
  void latest_statistics(DrawStatistics& s) const;

private:
  void draw_batches(PatchShape shape, const ShaderProgram& program, const DrawOptions& o, int n_total, int first_patch,
                    int n_patches) const;

  // By PatchOutput (quads have no wireframe program).
  std::array<ShapePrograms, 5> programs_;
  GlVertexArray empty_vao_;
  std::unique_ptr<QueryRing> statistics_;  // set while collecting statistics
  NormalisedFrame frame_;
  PatchLevelBound level_bound_;
};

}  // namespace gps
