#pragma once
// Which patch lies across each patch edge, and which patch owns each patch corner: what the
// tessellation evaluation shaders need to evaluate every point of a shared edge or corner from one
// canonical patch at one parameter, so that neighbours generate bit-identical vertices there
// (shaders/canonical_edge.glsl). Built once per topology from the plan table alone.
//
// PatchPlans::patch_neighbours holds 4 ints per patch edge, at 4·(corners·patch + k): edge k runs
// from patch corner k to corner k+1 (quads: PatchPlans::patch_edges; triangles: the corner points).
//   [0] the patch across the edge, or −1 (a mesh boundary); for a quad edge whole_beside_halves,
//       the half-size patch at the edge's `from` end;
//   [1] that patch's edge index m plus 4 if it runs the other way (4·reversed + m), or −1;
//   [2], [3] likewise for the half-size patch at the `to` end of a whole_beside_halves edge, else −1.
// PatchPlans::corner_owners holds 2 ints per patch corner, at 2·(corners·patch + c): the lowest
// patch with the same corner point (PatchPlans::patch_corner_points) and its corner index there.
//
// Canonical rules (the shader's, tested in tests/core/test_patch_adjacency.cpp): a point inside a
// shared edge is evaluated by the lower-numbered patch of two whole (or two half) edges, and by the
// half-size patch where a whole quad edge meets two halves; a corner by its owner.
#include <cstdint>
#include <vector>

#include "core/plans/patch_plans.h"

namespace gps {

/// Fills plans.patch_neighbours and plans.corner_owners (see above). Linear in the number of patches.
void add_patch_adjacency(PatchPlans& plans);

struct EdgeNeighbour {
  int patch = -1;  // −1: none
  int edge = -1;
  bool reversed = false;
};

/// Entry `which` (0 or 1) of patch edge k's record.
inline EdgeNeighbour edge_neighbour(const PatchPlans& plans, int patch, int k, int which = 0) {
  const int32_t* r = &plans.patch_neighbours[size_t(4 * (plans.corners() * patch + k) + 2 * which)];
  if (r[0] < 0) return {};
  return {r[0], r[1] & 3, (r[1] & 4) != 0};
}

}  // namespace gps
