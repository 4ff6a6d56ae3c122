#include "render/pipeline/kept_surface_triangles.h"

#include "core/mesh/mesh_connectivity.h"

namespace gps {

KeptTriangles kept_triangles(const PatchPlans& after, int n_before, const std::vector<KeptPatches>& kept,
                             const std::vector<int>& stale_corners) {
  const int n_patches = after.n_patches(), corners = after.corners();
  KeptTriangles out{std::vector<int>(size_t(n_before), -1), std::vector<char>(size_t(n_patches), 0)};
  std::vector<char> evaluated(size_t(n_patches), 1);  // not kept, or its corner output evaluated again
  for (const KeptPatches& run : kept)
    for (int i = 0; i < run.count; ++i) {
      out.new_number[size_t(run.old_first + i)] = run.first + i;
      evaluated[size_t(run.first + i)] = 0;
    }
  for (const int p : stale_corners) evaluated[size_t(p)] = 1;
#pragma omp parallel for schedule(static) if (n_patches >= kParallelFaces)
  for (int p = 0; p < n_patches; ++p) {
    bool changed = evaluated[size_t(p)] != 0;
    for (int k = 0; k < corners && !changed; ++k) {
      const size_t slot = size_t(corners * p + k);
      for (const int32_t q :
           {after.patch_neighbours[4 * slot], after.patch_neighbours[4 * slot + 2], after.corner_owners[2 * slot]})
        changed = changed || (q >= 0 && evaluated[size_t(q)] != 0);
    }
    out.changed[size_t(p)] = changed;
  }
  return out;
}

}  // namespace gps
