#pragma once
// The patch numbers the surface cache's captured vertices hold (the patch each was evaluated at, to
// weld and evaluate it again) brought to a change of topology that kept their patches under other
// numbers (shaders/renumber_patches_comp.glsl): the kept triangles are then those a capture of the
// new tables would store, bit for bit.
#include <vector>

#include "render/gl/gl_object.h"
#include "render/gl/shader_program.h"

namespace gps {

class StoredPatchRenumbering {
public:
  /// Needs a current GL context.
  StoredPatchRenumbering();
  StoredPatchRenumbering(const StoredPatchRenumbering&) = delete;
  StoredPatchRenumbering& operator=(const StoredPatchRenumbering&) = delete;

  /// Renumbers the first `count` captured vertices of `vertices` by `new_number` (per patch before:
  /// its number now; every patch they name must have one).
  void run(unsigned vertices, long long count, const std::vector<int>& new_number);

private:
  ShaderProgram program_;
  GlBuffer new_number_;
};

}  // namespace gps
