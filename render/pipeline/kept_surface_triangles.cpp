#include "render/pipeline/kept_surface_triangles.h"

namespace gps {

std::vector<int> patches_whose_triangles_change(const PatchPlans& after, const std::vector<KeptPatches>& kept,
                                                const std::vector<int>& stale_corners) {
  const int n_patches = after.n_patches(), corners = after.corners();
  std::vector<char> changed(size_t(n_patches), 1);
  for (const KeptPatches& run : kept)
    if (run.first == run.old_first)
      for (int p = run.first; p < run.first + run.count; ++p) changed[size_t(p)] = 0;
  for (const int p : stale_corners) changed[size_t(p)] = 1;
  std::vector<int> out;
  for (int p = 0; p < n_patches; ++p) {
    bool reads_changed = changed[size_t(p)] != 0;
    for (int k = 0; k < corners && !reads_changed; ++k) {
      const size_t slot = size_t(corners * p + k);
      for (const int32_t q : {after.patch_neighbours[4 * slot], after.patch_neighbours[4 * slot + 2],
                              after.corner_owners[2 * slot]})
        reads_changed = reads_changed || (q >= 0 && changed[size_t(q)] != 0);
    }
    if (reads_changed) out.push_back(p);
  }
  return out;
}

}  // namespace gps
