#pragma once
// Which patches a polygon mesh has and how their (u, v) domains sit on its faces (docs/design.md §2 step 1).
//
// Patches are numbered in base-face order. A quad is one patch: its corners, in the order
// the face lists them, sit at (u, v) = (0,0), (1,0), (1,1), (0,1). A face with n ≠ 4
// vertices c_0..c_{n-1} is n patches, after one Catmull-Clark step: patch first_patch(f) + k is the
// quad (c_k', e'(c_k, c_{k+1}), f', e'(c_{k-1}, c_k)) — vertex point, edge point, face point, edge
// point — with the same corner placement. Where a quad meets such a face, one quad edge meets two
// half-size patch edges; the limit curve along the edge is one curve, which subdivision halves
// exactly at the edge point, so both sides agree when the quad's edge samples at even steps what
// each half samples at all steps (the tessellation levels of core/plans/patch_plans.h's PatchEdgePart).
#include <vector>

#include "core/mesh/mesh_connectivity.h"
#include "core/reference/patch_param.h"

namespace gps {

/// Patch numbering of a mesh: first patch per face and the total.
struct PatchLayout {
  std::vector<int> first_patch;  // per face, plus one entry at the end holding the total
  int n_patches() const { return first_patch.empty() ? 0 : first_patch.back(); }
};

PatchLayout make_patch_layout(const PolygonTopology& faces);

}  // namespace gps
