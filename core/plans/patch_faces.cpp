#include "core/plans/patch_faces.h"

#include <algorithm>
#include <numeric>
#include <string>

#include "core/plans/patch_layout.h"
#include "core/support/error.h"

namespace gps {

std::vector<int> first_patches(const PolygonTopology& topology, const PatchPlans& plans) {
  std::vector<int> first;
  if (plans.shape == PatchShape::triangle) {  // one patch per triangle
    first.resize(size_t(topology.n_faces()) + 1);
    std::iota(first.begin(), first.end(), 0);
  } else {
    first = make_patch_layout(topology).first_patch;
  }
  if (first.empty() || first.back() != plans.n_patches())
    throw Error("the surface's patches do not follow its mesh's faces");
  return first;
}

std::vector<int> patch_faces(const PolygonTopology& topology, const PatchPlans& plans) {
  const std::vector<int> first = first_patches(topology, plans);
  std::vector<int> faces(size_t(plans.n_patches()));
  for (size_t f = 0; f + 1 < first.size(); ++f)
    for (int p = first[f]; p < first[f + 1]; ++p) faces[size_t(p)] = int(f);
  return faces;
}

std::vector<int> patches_of_faces(const PolygonTopology& topology, const PatchPlans& plans,
                                  const std::vector<int>& faces) {
  return patches_of_faces(first_patches(topology, plans), faces);
}

std::vector<int> patches_of_faces(const std::vector<int>& first, const std::vector<int>& faces) {
  std::vector<int> patches;
  for (const int f : faces) {
    if (f < 0 || size_t(f) + 1 >= first.size())
      throw Error("face " + std::to_string(f) + " is not in the mesh (" +
                  std::to_string(first.empty() ? 0 : first.size() - 1) + " faces)");
    for (int p = first[size_t(f)]; p < first[size_t(f) + 1]; ++p) patches.push_back(p);
  }
  std::sort(patches.begin(), patches.end());
  patches.erase(std::unique(patches.begin(), patches.end()), patches.end());
  return patches;
}

}  // namespace gps
