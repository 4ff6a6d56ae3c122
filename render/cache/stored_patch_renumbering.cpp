#include "render/cache/stored_patch_renumbering.h"

#include <glad/gl.h>

#include <algorithm>
#include <cstring>

#include "core/mesh/mesh_connectivity.h"
#include "render/gl/compute_limits.h"
#include "render/gl/gl_context.h"
#include "render/gl/gpu_layout.h"
#include "shaders/embedded_shaders.h"

namespace gps {

namespace {

constexpr size_t kVertexWords = 12, kPatchWord = 9;  // the patch evaluated: the patch, or −(patch + 1)

// The patch word `word` renumbered as shaders/renumber_patches_comp.glsl does; a word that names no
// patch before (which a capture never writes) stays as it is.
float renumbered(float word, const std::vector<int>& new_number) {
  const double n = double(new_number.size());
  if (word >= 0.0f && double(word) < n) return float(new_number[size_t(word)]);
  if (word < 0.0f && -double(word) <= n) return -float(new_number[size_t(-word) - 1] + 1);
  return word;
}

// `count` vertices from `from` to `to`, renumbered, on all cores.
void renumber_vertices(const float* from, float* to, long long count, const std::vector<int>& new_number) {
#pragma omp parallel for schedule(static) if (count >= kParallelFaces)
  for (long long i = 0; i < count; ++i) {
    float words[kVertexWords];
    std::memcpy(words, from + kVertexWords * size_t(i), sizeof words);
    words[kPatchWord] = renumbered(words[kPatchWord], new_number);
    std::memcpy(to + kVertexWords * size_t(i), words, sizeof words);
  }
}

// The first `count` vertices of `words` renumbered where they lie: only the patch words that change
// are written, so that the memory of the vertices whose patches keep their numbers is read, not written.
void renumber_in_place(float* words, long long count, const std::vector<int>& new_number) {
#pragma omp parallel for schedule(static) if (count >= kParallelFaces)
  for (long long i = 0; i < count; ++i) {
    float& word = words[kVertexWords * size_t(i) + kPatchWord];
    const float now = renumbered(word, new_number);
    if (std::memcmp(&now, &word, sizeof now) != 0) word = now;
  }
}

constexpr size_t kVertexBytes = kVertexWords * sizeof(float);

}  // namespace

void copy_stored_triangles(unsigned from, unsigned to, const std::vector<SurfaceBlocks::Moved>& runs) {
  for (const SurfaceBlocks::Moved& m : runs)
    if (m.triangles > 0)
      glCopyNamedBufferSubData(from, to, GLintptr(size_t(m.old_first_triangle) * 3 * kVertexBytes),
                               GLintptr(size_t(m.first_triangle) * 3 * kVertexBytes),
                               GLsizeiptr(size_t(m.triangles) * 3 * kVertexBytes));
}

StoredPatchRenumbering::StoredPatchRenumbering(bool on_the_cpu)
    : on_the_cpu_(on_the_cpu),
      program_("renumber_patches", {{GL_COMPUTE_SHADER, {shaders::gpu_layout, shaders::renumber_patches_comp}}}) {}

void StoredPatchRenumbering::run(unsigned vertices, long long count, const std::vector<int>& new_number) {
  if (count <= 0 || new_number.empty()) return;
  if (on_the_cpu_) {
    auto* words = static_cast<float*>(glMapNamedBufferRange(vertices, 0, GLsizeiptr(size_t(count) * kVertexBytes),
                                                            GL_MAP_READ_BIT | GL_MAP_WRITE_BIT));
    if (words) renumber_in_place(words, count, new_number);
    glUnmapNamedBuffer(vertices);
    check_gl_errors("renumbering the stored patches");
    return;
  }
  glNamedBufferData(new_number_, GLsizeiptr(new_number.size() * sizeof(int)), new_number.data(), GL_STREAM_DRAW);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingStoredVertices, vertices);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingPatchNumbers, new_number_);
  run_compute_pass(program_, int(count), false, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  check_gl_errors("renumbering the stored patches");
}

void StoredPatchRenumbering::copy(unsigned from, unsigned to, const std::vector<SurfaceBlocks::Moved>& runs,
                                  const std::vector<int>& new_number) {
  long long end_before = 0, end = 0;  // in triangles
  for (const SurfaceBlocks::Moved& m : runs)
    if (m.triangles > 0) {
      end_before = std::max(end_before, m.old_first_triangle + m.triangles);
      end = std::max(end, m.first_triangle + m.triangles);
    }
  if (end == 0) return;
  if (!on_the_cpu_) {
    copy_stored_triangles(from, to, runs);
    return run(to, 3 * end, new_number);
  }
  const auto* before = static_cast<const float*>(
      glMapNamedBufferRange(from, 0, GLsizeiptr(size_t(end_before) * 3 * kVertexBytes), GL_MAP_READ_BIT));
  auto* after = static_cast<float*>(glMapNamedBufferRange(to, 0, GLsizeiptr(size_t(end) * 3 * kVertexBytes),
                                                          GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT));
  if (before && after)
    for (const SurfaceBlocks::Moved& m : runs)
      if (m.triangles > 0)
        renumber_vertices(before + 3 * kVertexWords * size_t(m.old_first_triangle),
                          after + 3 * kVertexWords * size_t(m.first_triangle), 3 * m.triangles, new_number);
  if (after) glUnmapNamedBuffer(to);
  if (before) glUnmapNamedBuffer(from);
  check_gl_errors("copying and renumbering the stored patches");
}

}  // namespace gps
