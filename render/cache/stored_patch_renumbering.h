#pragma once
// The patch numbers the surface cache's captured vertices hold (the patch each was evaluated at, to
// weld and evaluate it again) brought to a change of topology that kept their patches under other
// numbers: the kept triangles are then those a capture of the new tables would store, bit for bit.
// On a GPU a compute pass renumbers them (shaders/renumber_patches_comp.glsl). Where the GL is a
// software renderer, its buffers lie in host memory: the CPU renumbers them there, on all cores, and
// renumbers the triangles a change moves as it copies them, in one pass over their bytes, where the
// compute pass would write every vertex's word one lane at a time after a copy.
#include <vector>

#include "render/cache/surface_blocks.h"
#include "render/gl/gl_object.h"
#include "render/gl/shader_program.h"

namespace gps {

/// Copies the captured triangles of `runs` from buffer `from` (at their old first triangle) to buffer
/// `to` (at their first triangle now) as they are.
void copy_stored_triangles(unsigned from, unsigned to, const std::vector<SurfaceBlocks::Moved>& runs);

class StoredPatchRenumbering {
public:
  /// Needs a current GL context. `on_the_cpu`: renumber in mapped host memory (a software renderer's
  /// way) rather than by the compute pass.
  explicit StoredPatchRenumbering(bool on_the_cpu);
  StoredPatchRenumbering(const StoredPatchRenumbering&) = delete;
  StoredPatchRenumbering& operator=(const StoredPatchRenumbering&) = delete;

  bool on_the_cpu() const { return on_the_cpu_; }

  /// Renumbers the first `count` captured vertices of `vertices` by `new_number` (per patch before:
  /// its number now; every patch they name must have one).
  void run(unsigned vertices, long long count, const std::vector<int>& new_number);
  /// Copies the triangles of `runs` from buffer `from` (at their old first triangle) to buffer `to` (at
  /// their first triangle now; they must tile its first ones) and renumbers them as run() does.
  void copy(unsigned from, unsigned to, const std::vector<SurfaceBlocks::Moved>& runs,
            const std::vector<int>& new_number);

private:
  bool on_the_cpu_;
  ShaderProgram program_;
  GlBuffer new_number_;
};

}  // namespace gps
