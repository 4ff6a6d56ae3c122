#include "render/pipeline/kept_corner_output.h"

#include <algorithm>

#include "core/mesh/mesh_connectivity.h"
#include "core/plans/patch_readers.h"

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
                                         const std::vector<KeptPatches>& kept) {
  const int n = after.corners();
  std::vector<char> evaluate(size_t(after.n_patches()), 1);
  std::vector<int> old_of_new(size_t(after.n_patches()), -1);
  for (const KeptPatches& run : kept)
    for (int i = 0; i < run.count; ++i) old_of_new[size_t(run.first + i)] = run.old_first + i;
  // A record names the same patch: the kept patch it names now was the one it named before.
  const auto same_patch = [&](int32_t now, int32_t was) {
    return now < 0 ? was < 0 : old_of_new[size_t(now)] == was && was >= 0;
  };
  for (const KeptPatches& run : kept) {
#pragma omp parallel for schedule(static) if (run.count >= kParallelFaces)
    for (int i = 0; i < run.count; ++i) {
      const size_t p = size_t(run.first + i), q = size_t(run.old_first + i);
      bool same = true;
      for (size_t c = 0; c < size_t(n) && same; ++c) {
        const size_t slot = size_t(n) * p + c, old_slot = size_t(n) * q + c;
        same = same_patch(after.corner_owners[2 * slot], before.corner_owners[2 * old_slot]) &&
               after.corner_owners[2 * slot + 1] == before.corner_owners[2 * old_slot + 1];
        for (size_t k = 0; k < 4 && same; k += 2)  // up to two neighbours per edge: patch, then code
          same = same_patch(after.patch_neighbours[4 * slot + k], before.patch_neighbours[4 * old_slot + k]) &&
                 after.patch_neighbours[4 * slot + k + 1] == before.patch_neighbours[4 * old_slot + k + 1];
      }
      evaluate[p] = !same;
    }
  }
  return evaluate;
}

std::vector<int> stale_corner_patches(const SurfaceTables& before, const SurfaceTables& after,
                                      const StencilDependents& dependents, const std::vector<int>& changed_or_new,
                                      const std::vector<KeptPatches>& kept, const std::vector<int>& origin) {
  std::vector<char> evaluate = patches_not_kept_alike(before.plans, after.plans, kept);
  const int n_base = after.stencils.n_base, n_patches = after.plans.n_patches();
  std::vector<int> changed;
  for (const int v : changed_or_new) {
    const size_t o = size_t(origin.empty() ? v : origin[size_t(v)]);  // −1: past every vertex
    if (o < size_t(before.stencils.n_base)) changed.push_back(v);
  }
  if (update_everything(changed.size(), size_t(n_base))) {
    std::fill(evaluate.begin(), evaluate.end(), 1);
  } else if (!changed.empty()) {  // a scan of the kept plans: cheaper than PatchReaders built for one change
    std::vector<char> point_changed(size_t(after.stencils.n_points()), 0);
    for (const int v : changed) point_changed[size_t(v)] = 1;
    for (const int r : rows_reading(dependents, changed)) point_changed[size_t(after.stencils.first_row() + r)] = 1;
#pragma omp parallel if (n_patches >= kParallelFaces)
    {
      std::vector<int> points;
#pragma omp for schedule(static)
      for (int p = 0; p < n_patches; ++p) {
        if (evaluate[size_t(p)]) continue;
        points.clear();
        append_patch_points(after.plans, p, points);
        for (const int q : points) evaluate[size_t(p)] |= point_changed[size_t(q)];
      }
    }
  }
  std::vector<int> patches;
  for (int p = 0; p < n_patches; ++p)
    if (evaluate[size_t(p)]) patches.push_back(p);
  return patches;
}

bool same_plans(const SurfaceTables& before, const SurfaceTables& after, const std::vector<KeptPatches>& kept,
                const std::vector<int>& origin) {
  const int n = before.plans.n_patches();
  if (kept.size() != 1 || kept[0] != KeptPatches{0, 0, n} || after.plans.n_patches() != n ||
      after.stencils.n_base != before.stencils.n_base)
    return false;
  for (size_t v = 0; v < origin.size(); ++v)
    if (origin[v] != int(v)) return false;
  return true;
}

}  // namespace gps
