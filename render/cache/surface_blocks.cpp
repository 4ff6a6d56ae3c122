#include "render/cache/surface_blocks.h"

#include <algorithm>

namespace gps {

int patches_per_block(int n_patches) { return std::clamp((n_patches + 511) / 512, 2, 256); }

void SurfaceBlocks::reset(int n_patches, int per_block) {
  n_patches_ = std::max(n_patches, 0);
  per_block_ = std::max(per_block, 1);
  first_triangle_.assign(size_t((n_patches_ + per_block_ - 1) / per_block_) + 1, 0);
  stale_.assign(size_t(size()), 0);
  stale_patches_ = 0;
}

void SurfaceBlocks::resize(int n_patches) {
  n_patches = std::max(n_patches, 0);
  const int first_changed = std::min(n_patches_, n_patches) / per_block_;
  std::vector<long long> counts(size_t((n_patches + per_block_ - 1) / per_block_), 0);
  std::vector<char> stale(counts.size(), 0);
  for (int b = 0; b < std::min(size(), int(counts.size())); ++b) {
    counts[size_t(b)] = b < first_changed ? triangles(b) : 0;
    stale[size_t(b)] = stale_[size_t(b)];
  }
  n_patches_ = n_patches;
  first_triangle_.assign(counts.size() + 1, 0);
  set_counts(counts);
  stale_ = std::move(stale);
  stale_patches_ = 0;
  for (int b = 0; b < size(); ++b) {
    if (b >= first_changed) stale_[size_t(b)] = 1;
    if (stale_[size_t(b)]) stale_patches_ += patches_in(b);
  }
}

int SurfaceBlocks::patches_in(int b) const { return std::min(per_block_, n_patches_ - first_patch(b)); }

void SurfaceBlocks::set_counts(const std::vector<long long>& counts) {
  for (size_t b = 0; b < counts.size() && b < size_t(size()); ++b)
    first_triangle_[b + 1] = first_triangle_[b] + counts[b];
}

void SurfaceBlocks::replace_counts(const std::vector<int>& blocks, const std::vector<long long>& counts) {
  std::vector<long long> all(static_cast<size_t>(size()));
  for (int b = 0; b < size(); ++b) all[size_t(b)] = triangles(b);
  for (size_t i = 0; i < blocks.size(); ++i) all[size_t(blocks[i])] = counts[i];
  set_counts(all);
}

void SurfaceBlocks::mark_stale(const std::vector<int>& patches) {
  for (const int p : patches) {
    const int b = p / per_block_;
    if (b < 0 || b >= size() || stale_[size_t(b)]) continue;
    stale_[size_t(b)] = 1;
    stale_patches_ += patches_in(b);
  }
}

void SurfaceBlocks::mark_all_stale() {
  std::fill(stale_.begin(), stale_.end(), 1);
  stale_patches_ = n_patches_;
}

std::vector<int> SurfaceBlocks::stale() const {
  std::vector<int> out;
  for (int b = 0; b < size(); ++b)
    if (stale_[size_t(b)]) out.push_back(b);
  return out;
}

void SurfaceBlocks::clear_stale() {
  std::fill(stale_.begin(), stale_.end(), 0);
  stale_patches_ = 0;
}

}  // namespace gps
