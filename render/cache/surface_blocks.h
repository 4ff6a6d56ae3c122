#pragma once
// The surface cache's blocks: runs of consecutive patches captured under one query each,
// so that an edit captures again only the blocks of the patches it changed. Keeps where each
// block's triangles lie in the stored buffer (the running sums of the counts) and which blocks are
// stale. No GL.
#include <cstddef>
#include <vector>

namespace gps {

/// Patches per block for a surface of `n_patches`: at most some 512 blocks, of 8 to 256 patches.
int patches_per_block(int n_patches);

class SurfaceBlocks {
public:
  /// `n_patches` in blocks of `per_block` (the last may be shorter): no triangles, nothing stale.
  void reset(int n_patches, int per_block);
  /// `n_patches` in blocks of the same size, where patches were added or removed at the end: the
  /// blocks whose patches stay keep their counts; those whose patches changed, from the first the
  /// end reached, are stale, the new ones with no triangles yet.
  void resize(int n_patches);

  int size() const { return int(first_triangle_.size()) - 1; }
  int n_patches() const { return n_patches_; }
  int first_patch(int b) const { return b * per_block_; }
  int patches_in(int b) const;
  long long first_triangle(int b) const { return first_triangle_[size_t(b)]; }
  long long triangles(int b) const { return first_triangle_[size_t(b) + 1] - first_triangle_[size_t(b)]; }
  long long total() const { return first_triangle_.back(); }

  /// The triangle count of every block (a full capture).
  void set_counts(const std::vector<long long>& counts);
  /// New counts of `blocks` (sorted): the later blocks move.
  void replace_counts(const std::vector<int>& blocks, const std::vector<long long>& counts);

  /// Marks the blocks holding any of `patches` stale.
  void mark_stale(const std::vector<int>& patches);
  void mark_all_stale();
  /// The stale blocks, in order.
  std::vector<int> stale() const;
  /// Patches in stale blocks.
  int stale_patches() const { return stale_patches_; }
  void clear_stale();

private:
  int n_patches_ = 0, per_block_ = 1;
  std::vector<long long> first_triangle_{0};  // one more than blocks
  std::vector<char> stale_;
  int stale_patches_ = 0;
};

}  // namespace gps
