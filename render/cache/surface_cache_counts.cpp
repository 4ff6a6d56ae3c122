// The surface cache's triangle counts from the patches' levels (render/cache/surface_cache.h): their
// check against a capture's queries, their sums by block, and a capture made by them.
#include <glad/gl.h>

#include <algorithm>

#include "render/cache/surface_cache.h"

namespace gps {

std::vector<int> SurfaceCache::checked_blocks() const {
  const int n = blocks_.size(), step = std::max(1, int((blocks_.n_patches() + kCheckedPatches - 1) / kCheckedPatches));
  std::vector<int> blocks;
  for (int b = 0; b < n; b += step) blocks.push_back(b);
  return blocks;
}

std::vector<int> SurfaceCache::checked_patches() const { return patches_of(checked_blocks()); }

void SurfaceCache::check_patch_triangles(const std::vector<int>& counts) {
  const std::vector<int> blocks = checked_blocks();
  const std::vector<long long> sums = block_sums(blocks, counts);
  patch_triangles_agree_ = !sums.empty() && !counts_missed_;
  for (size_t i = 0; i < sums.size(); ++i)
    patch_triangles_agree_ = patch_triangles_agree_ && sums[i] == blocks_.triangles(blocks[i]);
}

std::vector<int> SurfaceCache::patches_of(const std::vector<int>& blocks) const {
  std::vector<int> patches;
  for (const int b : blocks)
    for (int p = blocks_.first_patch(b); p < blocks_.first_patch(b) + blocks_.patches_in(b); ++p) patches.push_back(p);
  return patches;
}

std::vector<long long> SurfaceCache::block_sums(const std::vector<int>& blocks, const std::vector<int>& counts) const {
  size_t patches = 0;
  for (const int b : blocks) patches += size_t(blocks_.patches_in(b));
  if (counts.size() != patches) return {};
  std::vector<long long> sums(blocks.size(), 0);
  size_t next = 0;
  for (size_t i = 0; i < blocks.size(); ++i)
    for (int k = 0; k < blocks_.patches_in(blocks[i]); ++k) sums[i] += counts[next++];
  return sums;
}

std::vector<long long> SurfaceCache::counted_triangles(const std::vector<int>& blocks,
                                                       const PatchTriangles& patch_triangles) const {
  return block_sums(blocks, patch_triangles(patches_of(blocks)));
}

bool SurfaceCache::capture_counted(const std::vector<int>& all, const DrawPatches& draw_patches, bool rasterize,
                                   const std::vector<int>& patch_counts) {
  const std::vector<long long> counts = block_sums(all, patch_counts);
  if (counts.size() != all.size()) return false;
  long long total = 0;
  for (const long long c : counts) total += c;
  if (total >= most_triangles()) return false;  // refused by the capture block by block
  reserve(buffer_, capacity_, total);
  std::vector<long long> captured;
  long long written = -1;
  if (!capture_blocks(buffer_, capacity_, all, draw_patches, captured, rasterize, &counts, &written)) return false;
  if (written != total) {
    counts_missed_ = true;
    patch_triangles_agree_ = false;
    return false;
  }
  blocks_.set_counts(counts);
  return true;
}

}  // namespace gps
