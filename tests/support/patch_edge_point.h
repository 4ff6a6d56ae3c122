#pragma once
// Patch parameters along a patch's edges, as the tessellation stages place them.
#include <utility>

#include "core/plans/patch_plans.h"

namespace gps::test {

/// (u, v) of the point at fraction t along patch edge k, which runs from corner k to corner k + 1
/// (t = 0: corner k).
inline std::pair<double, double> edge_point(PatchShape shape, int k, double t) {
  if (shape == PatchShape::triangle)
    return k == 0 ? std::pair{t, 0.0} : k == 1 ? std::pair{1 - t, t} : std::pair{0.0, 1 - t};
  return k == 0   ? std::pair{t, 0.0}
         : k == 1 ? std::pair{1.0, t}
         : k == 2 ? std::pair{1 - t, 1.0}
                  : std::pair{0.0, 1 - t};
}

}  // namespace gps::test
