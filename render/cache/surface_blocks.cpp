#include "render/cache/surface_blocks.h"

#include <algorithm>

namespace gps {

int patches_per_block(int n_patches) { return std::clamp((n_patches + 8191) / 8192, 4, 256); }

void SurfaceBlocks::reset(int n_patches, int per_block) {
  n_patches = std::max(n_patches, 0);
  per_block_ = std::max(per_block, 1);
  first_patch_.clear();
  for (int p = 0; p < n_patches; p += per_block_) first_patch_.push_back(p);
  first_patch_.push_back(n_patches);
  first_triangle_.assign(first_patch_.size(), 0);
  stale_.assign(size_t(size()), 0);
  stale_patches_ = 0;
  ends_kept_.clear();
}

std::vector<SurfaceBlocks::Moved> SurfaceBlocks::follow(int n_patches, const std::vector<int>& new_number,
                                                        const std::vector<char>& changed) {
  n_patches = std::max(n_patches, 0);
  // A block whose numbered patches all moved by one shift stays a block, of the patches at its old
  // ones shifted, with its triangles where they lie: stale where one of those changes or its old
  // patches include one without a number (captured again in place, most often to the same count).
  struct Kept {
    int block, first;
    bool stale;
    int lead = 0, trail = 0;  // of a block stale for its changed patches: the patches at its ends that stay
  };
  std::vector<Kept> kept;
  int end = 0;  // new patches before it are taken
  for (int b = 0; b < size(); ++b) {
    const int first = first_patch(b);
    bool numbered = false, one_shift = true, stale = stale_[size_t(b)] != 0;
    int shift = 0;
    for (int i = 0; i < patches_in(b); ++i) {
      const int now = new_number[size_t(first + i)];
      if (now < 0) {
        stale = true;
        continue;
      }
      one_shift = one_shift && (!numbered || now - (first + i) == shift);
      shift = now - (first + i);
      numbered = true;
    }
    const int now = first + shift;
    if (!numbered || !one_shift || now < end || now + patches_in(b) > n_patches) continue;
    const bool stale_before = stale_[size_t(b)] != 0;
    const auto stays = [&](int i) { return new_number[size_t(first + i)] == now + i && !changed[size_t(now + i)]; };
    int lead = 0, trail = 0;
    while (lead < patches_in(b) && stays(lead)) ++lead;
    while (trail < patches_in(b) - lead && stays(patches_in(b) - 1 - trail)) ++trail;
    stale = stale || lead < patches_in(b);
    if (stale_before || lead == patches_in(b)) lead = trail = 0;
    kept.push_back({b, now, stale, lead, trail});
    end = now + patches_in(b);
  }
  std::vector<int> first_patch;
  std::vector<long long> counts;
  std::vector<char> stale;
  std::vector<Moved> moved;
  ends_kept_.clear();
  long long triangle = 0;
  const auto add_stale = [&](int from, int to) {  // new patches [from, to) in blocks of per_block_
    for (int p = from; p < to; p += per_block_) first_patch.push_back(p), counts.push_back(0), stale.push_back(1);
  };
  int next = 0;
  for (const Kept& k : kept) {
    add_stale(next, k.first);
    if (k.lead + k.trail > 0) ends_kept_.push_back({int(first_patch.size()), k.lead, k.trail});
    first_patch.push_back(k.first);
    counts.push_back(triangles(k.block));
    stale.push_back(k.stale);
    moved.push_back({first_patch_[size_t(k.block)], k.first, patches_in(k.block), first_triangle(k.block), triangle,
                     triangles(k.block)});
    triangle += triangles(k.block);
    next = k.first + patches_in(k.block);
  }
  add_stale(next, n_patches);
  first_patch.push_back(n_patches);
  assign(std::move(first_patch), counts, std::move(stale));
  return moved;
}

void SurfaceBlocks::assign(std::vector<int> first_patch, const std::vector<long long>& counts,
                           std::vector<char> stale) {
  first_patch_ = std::move(first_patch);
  first_triangle_.assign(first_patch_.size(), 0);
  set_counts(counts);
  stale_ = std::move(stale);
  stale_patches_ = 0;
  for (int b = 0; b < size(); ++b)
    if (stale_[size_t(b)]) stale_patches_ += patches_in(b);
}

std::vector<int> SurfaceBlocks::kept_end_patches() const {
  std::vector<int> patches;
  for (const KeptEnds& k : ends_kept_) {
    const int first = first_patch(k.block), end = first + patches_in(k.block);
    for (int p = first; p < first + k.lead; ++p) patches.push_back(p);
    for (int p = end - k.trail; p < end; ++p) patches.push_back(p);
  }
  return patches;
}

void SurfaceBlocks::split_kept_ends(const std::vector<int>& counts) {
  std::vector<int> first_patch;
  std::vector<long long> triangles;
  std::vector<char> stale;
  size_t next = 0, count = 0;  // the next block with kept ends, and its patches' first count
  const auto sum = [&](int n) {
    long long total = 0;
    for (int i = 0; i < n; ++i) total += counts[count++];
    return total;
  };
  // A block joins the one before it where both are stale or both not, and together they hold no more
  // patches than a block of the usual size: splits of one change after another do not leave ever
  // smaller blocks (each costs a query and a draw when captured).
  const auto add = [&](int first, int patches, long long n, bool is_stale) {
    if (!stale.empty() && (stale.back() != 0) == is_stale && first + patches - first_patch.back() <= per_block_) {
      triangles.back() += n;
      return;
    }
    first_patch.push_back(first), triangles.push_back(n), stale.push_back(is_stale);
  };
  for (int b = 0; b < size(); ++b) {
    const int first = first_patch_[size_t(b)], patches = patches_in(b);
    if (next == ends_kept_.size() || ends_kept_[next].block != b) {
      add(first, patches, this->triangles(b), stale_[size_t(b)] != 0);
      continue;
    }
    const KeptEnds& k = ends_kept_[next++];
    const long long lead = sum(k.lead), trail = sum(k.trail), middle = this->triangles(b) - lead - trail;
    if (middle < 0) {  // counts that cannot be this block's: not split
      add(first, patches, this->triangles(b), stale_[size_t(b)] != 0);
      continue;
    }
    if (k.lead > 0) add(first, k.lead, lead, false);
    add(first + k.lead, patches - k.lead - k.trail, middle, true);
    if (k.trail > 0) add(first + patches - k.trail, k.trail, trail, false);
  }
  first_patch.push_back(n_patches());
  assign(std::move(first_patch), triangles, std::move(stale));
  ends_kept_.clear();
}

int SurfaceBlocks::block_of(int patch) const {
  return int(std::upper_bound(first_patch_.begin(), first_patch_.end(), patch) - first_patch_.begin()) - 1;
}

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

int SurfaceBlocks::stale_patches_past_kept_ends() const {
  int patches = stale_patches_;
  for (const KeptEnds& k : ends_kept_) patches -= k.lead + k.trail;
  return patches;
}

// Any other change of patches than follow()'s may reach the kept ends: they are given up.
void SurfaceBlocks::mark_stale(const std::vector<int>& patches) {
  ends_kept_.clear();
  for (const int p : patches) {
    if (p < 0 || p >= n_patches()) continue;
    const int b = block_of(p);
    if (stale_[size_t(b)]) continue;
    stale_[size_t(b)] = 1;
    stale_patches_ += patches_in(b);
  }
}

void SurfaceBlocks::mark_all_stale() {
  ends_kept_.clear();
  std::fill(stale_.begin(), stale_.end(), 1);
  stale_patches_ = n_patches();
}

std::vector<int> SurfaceBlocks::stale() const {
  std::vector<int> out;
  for (int b = 0; b < size(); ++b)
    if (stale_[size_t(b)]) out.push_back(b);
  return out;
}

void SurfaceBlocks::clear_stale() {
  ends_kept_.clear();
  std::fill(stale_.begin(), stale_.end(), 0);
  stale_patches_ = 0;
}

std::vector<SurfaceBlocks::Moved> joined_runs(const std::vector<SurfaceBlocks::Moved>& moved) {
  std::vector<SurfaceBlocks::Moved> runs;
  for (const SurfaceBlocks::Moved& m : moved) {
    if (!runs.empty()) {
      SurfaceBlocks::Moved& r = runs.back();
      if (m.old_first_patch == r.old_first_patch + r.patches && m.first_patch == r.first_patch + r.patches &&
          m.old_first_triangle == r.old_first_triangle + r.triangles &&
          m.first_triangle == r.first_triangle + r.triangles) {
        r.patches += m.patches;
        r.triangles += m.triangles;
        continue;
      }
    }
    runs.push_back(m);
  }
  return runs;
}

}  // namespace gps
