#pragma once
// The surface cache's blocks: runs of consecutive patches captured under one query each,
// so that an edit captures again only the blocks of the patches it changed. Keeps where each
// block's triangles lie in the stored buffer (the running sums of the counts) and which blocks are
// stale. No GL.
#include <cstddef>
#include <vector>

namespace gps {

/// Patches per block for a surface of `n_patches`: at most some 8192 blocks, of 4 to 256 patches. Small
/// enough that a change spread along the face numbering (a loop cut around the mesh: hundreds of kept
/// runs, each boundary a block that cannot follow its patches) leaves most blocks kept and captures
/// few patches again; what costs per block (a query, a copy) stays small beside what costs per patch.
int patches_per_block(int n_patches);

class SurfaceBlocks {
public:
  /// `n_patches` in blocks of `per_block` (the last may be shorter): no triangles, nothing stale.
  void reset(int n_patches, int per_block);

  /// A block kept through a change of topology: its patches, numbered from `old_first_patch` before
  /// and from `first_patch` now, and its triangles, which lay from `old_first_triangle` and now lie from
  /// `first_triangle`.
  struct Moved {
    int old_first_patch, first_patch, patches;
    long long old_first_triangle, first_triangle, triangles;
  };
  /// The blocks after a change of topology to `n_patches` patches: `new_number` gives each old patch's
  /// number now (−1: none), `changed` flags the new patches whose triangles change. A block whose
  /// numbered patches all moved by one shift stays a block of its patches shifted, with its
  /// triangles, stale where one of them changed or had no number; the new patches no such block
  /// holds form stale blocks of at most the same size, with no triangles yet. Returns where the kept
  /// blocks' triangles move, in order.
  std::vector<Moved> follow(int n_patches, const std::vector<int>& new_number, const std::vector<char>& changed);

  /// The patches at the ends of blocks that follow() left stale for some of their patches, which stay
  /// as they were: per such block, in order, its leading ones and its trailing ones.
  std::vector<int> kept_end_patches() const;
  /// Given those patches' triangle counts (render/cache/patch_triangle_counts.h), each such block split
  /// where its triangles lie: its leading and trailing patches that stay, blocks of their own, not
  /// stale, and the patches between, stale. A block whose counts do not fit its triangles stays whole.
  /// Neighbouring blocks alike in staleness join where they fit in a block of the usual size.
  void split_kept_ends(const std::vector<int>& counts);
  /// Patches in stale blocks once split_kept_ends() has split them.
  int stale_patches_past_kept_ends() const;

  int size() const { return int(first_triangle_.size()) - 1; }
  int n_patches() const { return first_patch_.back(); }
  int first_patch(int b) const { return first_patch_[size_t(b)]; }
  int patches_in(int b) const { return first_patch_[size_t(b) + 1] - first_patch_[size_t(b)]; }
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
  int block_of(int patch) const;
  /// Blocks starting at `first_patch` (one more: the patch count), of `counts` triangles, stale as flagged.
  void assign(std::vector<int> first_patch, const std::vector<long long>& counts, std::vector<char> stale);

  int per_block_ = 1;
  std::vector<int> first_patch_{0};           // one more than blocks: the last is the patch count
  std::vector<long long> first_triangle_{0};  // one more than blocks
  std::vector<char> stale_;
  int stale_patches_ = 0;
  struct KeptEnds {
    int block, lead, trail;  // patches at its start and its end that stay
  };
  std::vector<KeptEnds> ends_kept_;  // since the last follow(), in block order
};

/// `moved` (in order) with each run of blocks that lie one after the other before and now, in their
/// patches and their triangles, as one: what follows a change of topology copies a run at a time.
std::vector<SurfaceBlocks::Moved> joined_runs(const std::vector<SurfaceBlocks::Moved>& moved);

}  // namespace gps
