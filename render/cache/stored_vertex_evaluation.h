#pragma once
// Evaluates the surface cache's welded vertices again after an edit (shaders/stored_vertex_evaluation_comp.glsl),
// in a compute pass instead of a transform feedback capture of the tessellation: each welded vertex
// keeps the patch and (u, v) its tessellation vertex was evaluated at, which an edit at the same
// levels does not change, and is evaluated there once, where the tessellation stage evaluates a
// point once per patch around it, on llvmpipe in one thread. The plan buffers are bound
// (render/pipeline/plan_buffers.h).
#include <vector>

#include "core/plans/patch_plans.h"
#include "render/gl/gl_object.h"
#include "render/gl/shader_program.h"
#include "render/gl/shape_programs.h"
#include "render/gl/point_precision.h"

namespace gps {

class StoredVertexEvaluation {
public:
  /// A block of the surface cache: its welded vertices lie from `first` on, fewer than `bound`; its
  /// patches are `patches` from `first_patch` on.
  struct Block {
    int block;
    long long first, bound;
    int first_patch, patches;
  };
  /// Needs a current GL context.
  StoredVertexEvaluation();
  StoredVertexEvaluation(const StoredVertexEvaluation&) = delete;
  StoredVertexEvaluation& operator=(const StoredVertexEvaluation&) = delete;
  /// The programs for plan points of `precision` from now on (built at its first use).
  void set_precision(PointPrecision precision);
  /// Evaluates the welded vertices of `blocks` (of the buffers bound at kBindingWeldedVertices and
  /// kBindingWeldedParameters) on `plans`, as many per block as `welded_counts` holds
  /// (render/cache/stored_vertex_weld.h), in one indirect dispatch whose work groups run across the
  /// blocks, or as many as the device's work groups per dispatch (or a lower `group_limit` > 0)
  /// require; a storage barrier follows. The blocks whose plans hold no extraordinary node are
  /// evaluated by a program built without that branch, which a software driver otherwise runs,
  /// masked off, in every batch (shaders/plan_eval.glsl, GPS_LEAVES_ONLY).
  void run(const PatchPlans& plans, const std::vector<Block>& blocks, unsigned welded_counts, int group_limit);

private:
  /// The dispatches over `blocks` by `programs`.
  void run_with(const ShapePrograms& programs, PatchShape shape, const std::vector<Block>& blocks,
                unsigned welded_counts, int group_limit);
  /// One indirect dispatch over `blocks`.
  void dispatch(const ShaderProgram& program, const std::vector<Block>& blocks, unsigned welded_counts);

  ShapePrograms programs_;
  ShapePrograms leaf_programs_;  // for blocks of plans without an extraordinary node
  ShaderProgram groups_program_;
  GlBuffer blocks_, groups_;
};

}  // namespace gps
