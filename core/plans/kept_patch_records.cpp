#include "core/plans/kept_patch_records.h"

#include <algorithm>

#include "core/mesh/mesh_connectivity.h"

namespace gps {

bool kept_runs_fit(const std::vector<KeptPatches>& kept, int n_before, int n_after) {
  int end = 0, old_end = 0;
  for (const KeptPatches& run : kept) {
    if (run.count <= 0 || run.first < end || run.old_first < old_end) return false;
    end = run.first + run.count;
    old_end = run.old_first + run.count;
    if (end > n_after || old_end > n_before) return false;
  }
  return true;
}

std::vector<char> patches_not_kept_alike(const PatchPlans& before, const PatchPlans& after,
                                         const std::vector<KeptPatches>& kept, const std::vector<int>* relinked) {
  const int n = after.corners();
  std::vector<char> evaluate(size_t(after.n_patches()), 1);
  for (const KeptPatches& run : kept) std::fill_n(evaluate.begin() + run.first, run.count, char(0));
  // A patch's old number (−1: not kept): from a table where every kept patch is compared, else from
  // the run that holds it.
  std::vector<int> old_of_new;
  if (!relinked) {
    old_of_new.assign(size_t(after.n_patches()), -1);
    for (const KeptPatches& run : kept)
      for (int i = 0; i < run.count; ++i) old_of_new[size_t(run.first + i)] = run.old_first + i;
  }
  const auto old_of = [&](int32_t now) {
    if (!old_of_new.empty()) return old_of_new[size_t(now)];
    const auto run =
        std::upper_bound(kept.begin(), kept.end(), now, [](int32_t p, const KeptPatches& r) { return p < r.first; });
    if (run == kept.begin() || now >= std::prev(run)->first + std::prev(run)->count) return -1;
    return std::prev(run)->old_first + (now - std::prev(run)->first);
  };
  // A record names the same patch: the kept patch it names now was the one it named before.
  const auto same_patch = [&](int32_t now, int32_t was) { return now < 0 ? was < 0 : was >= 0 && old_of(now) == was; };
  const auto compare = [&](int p, int q) {
    bool same = true;
    for (size_t c = 0; c < size_t(n) && same; ++c) {
      const size_t slot = size_t(n) * size_t(p) + c, old_slot = size_t(n) * size_t(q) + c;
      same = same_patch(after.corner_owners[2 * slot], before.corner_owners[2 * old_slot]) &&
             after.corner_owners[2 * slot + 1] == before.corner_owners[2 * old_slot + 1];
      for (size_t k = 0; k < 4 && same; k += 2)  // up to two neighbours per edge: patch, then code
        same = same_patch(after.patch_neighbours[4 * slot + k], before.patch_neighbours[4 * old_slot + k]) &&
               after.patch_neighbours[4 * slot + k + 1] == before.patch_neighbours[4 * old_slot + k + 1];
    }
    evaluate[size_t(p)] = !same;
  };
  if (relinked) {
    for (const int p : *relinked)
      if (const int q = old_of(p); q >= 0) compare(p, q);
    return evaluate;
  }
  for (const KeptPatches& run : kept) {
#pragma omp parallel for schedule(static) if (run.count >= kParallelFaces)
    for (int i = 0; i < run.count; ++i) compare(run.first + i, run.old_first + i);
  }
  return evaluate;
}

}  // namespace gps
