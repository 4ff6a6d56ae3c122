#include "render/cache/stored_patch_levels.h"

#include <glad/gl.h>

#include <algorithm>

#include "render/gl/compute_limits.h"
#include "render/gl/gl_context.h"
#include "render/gl/gpu_layout.h"
#include "shaders/embedded_shaders.h"

namespace gps {

StoredPatchLevels::StoredPatchLevels()
    : programs_(
          plan_compute_programs("patch_level_check", false, {shaders::tess_levels, shaders::patch_level_check_comp})) {}

void StoredPatchLevels::set_precision(PointPrecision precision) { programs_.set_precision(precision); }

void StoredPatchLevels::reserve(int n_patches) {
  if (n_patches <= capacity_ && 4 * n_patches >= capacity_) return;
  capacity_ = std::max(n_patches, 1);
  glNamedBufferData(levels_, GLsizeiptr(capacity_) * kBytesPerPatch, nullptr, GL_DYNAMIC_COPY);
}

void StoredPatchLevels::follow(int n_patches, const std::vector<SurfaceBlocks::Moved>& moved) {
  if (moved.empty()) return;  // not followed: the next capture records every patch
  const int capacity = std::max(n_patches, 1);
  glNamedBufferData(spare_, GLsizeiptr(capacity) * kBytesPerPatch, nullptr, GL_DYNAMIC_COPY);
  for (const SurfaceBlocks::Moved& m : joined_runs(moved))
    if (m.old_first_patch + m.patches <= capacity_ && m.first_patch + m.patches <= capacity)
      glCopyNamedBufferSubData(levels_, spare_, GLintptr(m.old_first_patch) * kBytesPerPatch,
                               GLintptr(m.first_patch) * kBytesPerPatch, GLsizeiptr(m.patches) * kBytesPerPatch);
  std::swap(levels_, spare_);
  glNamedBufferData(spare_, 0, nullptr, GL_DYNAMIC_COPY);
  capacity_ = capacity;
}

void StoredPatchLevels::record(PatchShape shape, int n_patches, int group_limit) {
  reserve(n_patches);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingPatchLevels, levels_);
  run_compute_pass(program(shape), n_patches, false, group_limit);
  check_gl_errors("recording the patches' levels");
}

std::vector<char> StoredPatchLevels::changed(PatchShape shape, const std::vector<Block>& blocks, int group_limit) {
  std::vector<GLint> listed;  // patch, its block in the list
  for (size_t b = 0; b < blocks.size(); ++b)
    for (int p = blocks[b].first; p < blocks[b].first + blocks[b].count; ++p)
      listed.insert(listed.end(), {GLint(p), GLint(b)});
  std::vector<GLuint> changes(blocks.size(), 0u);
  if (listed.empty()) return std::vector<char>(blocks.size(), 0);
  glNamedBufferData(patches_, GLsizeiptr(listed.size() * sizeof(GLint)), listed.data(), GL_STREAM_DRAW);
  glNamedBufferData(changes_, GLsizeiptr(changes.size() * sizeof(GLuint)), changes.data(), GL_STREAM_READ);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingPatchLevels, levels_);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingLevelPatches, patches_);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingLevelChanges, changes_);
  run_compute_pass(program(shape), int(listed.size() / 2), true, group_limit);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(changes_, 0, GLsizeiptr(changes.size() * sizeof(GLuint)), changes.data());
  check_gl_errors("checking the patches' levels");
  std::vector<char> out(blocks.size());
  for (size_t b = 0; b < blocks.size(); ++b) out[b] = changes[b] != 0u;
  return out;
}

}  // namespace gps
