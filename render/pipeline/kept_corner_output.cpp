#include "render/pipeline/kept_corner_output.h"

#include <algorithm>

#include "core/mesh/mesh_connectivity.h"
#include "core/plans/patch_faces.h"
#include "core/plans/patch_readers.h"

namespace gps {

std::vector<int> stale_corner_patches(const SurfaceTables& before, const SurfaceTables& after,
                                      const CovarianceMesh& mesh, const std::vector<int>& first,
                                      const std::function<const StencilDependents&()>& dependents,
                                      const std::vector<int>& changed_or_new, const PlanChange& change,
                                      const std::vector<int>& origin) {
  std::vector<char> evaluate =
      patches_not_kept_alike(before.plans, after.plans, change.kept, change.relinked ? &*change.relinked : nullptr);
  const int n_base = after.stencils.n_base, n_patches = after.plans.n_patches();
  std::vector<int> changed;
  for (const int v : changed_or_new) {
    const size_t o = size_t(origin.empty() ? v : origin[size_t(v)]);  // −1: past every vertex
    if (o < size_t(before.stencils.n_base)) changed.push_back(v);
  }
  if (update_everything(changed.size(), size_t(n_base))) {
    std::fill(evaluate.begin(), evaluate.end(), 1);
  } else if (!changed.empty()) {  // a scan of the kept plans near them: cheaper than PatchReaders built for one change
    std::vector<char> point_changed(size_t(after.stencils.n_points()), 0);
    for (const int v : changed) point_changed[size_t(v)] = 1;
    for (const int r : rows_reading(dependents(), changed)) point_changed[size_t(after.stencils.first_row() + r)] = 1;
    const std::vector<int> near =
        patches_of_faces(first, faces_reading(mesh.topology(), mesh.connectivity(), {}, changed));
    const int n_near = int(near.size());
#pragma omp parallel if (n_near >= kParallelFaces)
    {
      std::vector<int> points;
#pragma omp for schedule(static)
      for (int i = 0; i < n_near; ++i) {
        const size_t p = size_t(near[size_t(i)]);
        if (evaluate[p]) continue;
        points.clear();
        append_patch_points(after.plans, int(p), points);
        for (const int q : points) evaluate[p] |= point_changed[size_t(q)];
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
