#include "render/pipeline/kept_surface_triangles.h"

#include <algorithm>

#include "core/mesh/mesh_connectivity.h"

namespace gps {

namespace {

// Whether patch p of `after` is evaluated again or evaluates a boundary point from one that is.
bool triangles_change(const PatchPlans& after, const std::vector<char>& evaluated, int p) {
  if (evaluated[size_t(p)]) return true;
  for (int k = 0; k < after.corners(); ++k) {
    const size_t slot = size_t(after.corners() * p + k);
    for (const int32_t q :
         {after.patch_neighbours[4 * slot], after.patch_neighbours[4 * slot + 2], after.corner_owners[2 * slot]})
      if (q >= 0 && evaluated[size_t(q)] != 0) return true;
  }
  return false;
}

}  // namespace

KeptTriangles kept_triangles(const CovarianceMesh& mesh, const PatchPlans& after, const std::vector<int>& first,
                             int n_before, const std::vector<KeptPatches>& kept,
                             const std::vector<int>& stale_corners) {
  const int n_patches = after.n_patches();
  KeptTriangles out{std::vector<int>(size_t(n_before), -1), std::vector<char>(size_t(n_patches), 0)};
  std::vector<char> evaluated(size_t(n_patches), 1);  // not kept, or its corner output evaluated again
  int n_kept = 0;
  for (const KeptPatches& run : kept) {
    for (int i = 0; i < run.count; ++i) {
      out.new_number[size_t(run.old_first + i)] = run.first + i;
      evaluated[size_t(run.first + i)] = 0;
    }
    n_kept += run.count;
  }
  for (const int p : stale_corners) evaluated[size_t(p)] = 1;
  if (4 * (size_t(n_patches - n_kept) + stale_corners.size()) > size_t(n_patches)) {
#pragma omp parallel for schedule(static) if (n_patches >= kParallelFaces)
    for (int p = 0; p < n_patches; ++p) out.changed[size_t(p)] = triangles_change(after, evaluated, p);
    return out;
  }
  // A patch's edge neighbours and corner owners lie on faces that share a vertex with its own: only
  // the patches of the faces around those of the patches evaluated again can change.
  std::vector<int> faces;  // of the patches evaluated again, ascending
  for (int p = 0; p < n_patches; ++p)
    if (evaluated[size_t(p)]) {
      const int f = int(std::upper_bound(first.begin(), first.end(), p) - first.begin()) - 1;
      if (faces.empty() || faces.back() != f) faces.push_back(f);
    }
  for (const int g : faces_around(mesh.topology(), mesh.connectivity(), faces))
    for (int p = first[size_t(g)]; p < first[size_t(g) + 1]; ++p)
      out.changed[size_t(p)] = triangles_change(after, evaluated, p);
  return out;
}

}  // namespace gps
