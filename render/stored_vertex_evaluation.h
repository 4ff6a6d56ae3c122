#pragma once
// Evaluates the surface cache's welded vertices again after an edit (shaders/stored_vertex_evaluation_comp.glsl),
// in a compute pass instead of a transform feedback capture of the tessellation: each welded vertex
// keeps the patch and (u, v) its tessellation vertex was evaluated at, which an edit at the same
// levels does not change, and is evaluated there once, where the tessellation stage evaluates a
// point once per patch around it, on llvmpipe in one thread. The plan buffers are bound (render/plan_buffers.h).
#include "core/plan_table.h"
#include "render/shader_program.h"

namespace gps {

class StoredVertexEvaluation {
public:
  /// Needs a current GL context.
  StoredVertexEvaluation();
  /// Evaluates the welded vertices from `first` on, fewer than `bound`, of the buffers bound at
  /// kBindingWeldedVertices and kBindingWeldedParameters, for patches of `shape`, in the work
  /// groups that the bound GL_DISPATCH_INDIRECT_BUFFER holds at `dispatch_offset` (a block's,
  /// render/stored_vertex_weld.h); a storage barrier follows.
  void run(PatchShape shape, long long first, long long bound, long long dispatch_offset) const;

private:
  ShaderProgram quads_, triangles_;
};

}  // namespace gps
