#pragma once
// Which patches an edit changes (for the surface cache's partial re-capture): every patch
// whose tessellated vertices depend on a plan point. A patch's vertices read its plan's nets, its
// corner points and the ends of its edges (tessellation levels), and on its boundary the points of
// the canonical patch of each shared edge or corner (core/plans/patch_adjacency.h). Built once per
// topology from the plan table alone.
#include <vector>

#include "core/mesh/mesh_connectivity.h"
#include "core/plans/patch_plans.h"

namespace gps {

/// Appends the points patch `p` reads to `out` (its plan's nets, its corner points, its edges' ends),
/// unsorted and with repeats.
void append_patch_points(const PatchPlans& plans, int p, std::vector<int>& out);

class PatchReaders {
public:
  /// `n_points`: base vertices plus stencil rows (StencilTable::n_points()).
  PatchReaders(const PatchPlans& plans, int n_points);

  /// The patches whose generated vertices change when `points` change (point indices: base
  /// vertices, then n_base + row), sorted, without repeats: the patches that read any of them, and
  /// those that evaluate a boundary point from one of these (their canonical edge or corner patch).
  std::vector<int> patches_changed_by(const std::vector<int>& points) const;

  int n_patches() const { return n_patches_; }

private:
  int n_patches_ = 0;
  std::vector<int> point_offsets_, point_patches_;        // per point: the patches that read it
  std::vector<int> canonical_offsets_, canonical_users_;  // per patch: the patches evaluating a boundary point from it
};

/// PatchReaders::patches_changed_by for the base vertices `vertices` and the stencil rows `rows` that
/// read them (points first_row + row: StencilTable::first_row), found from the mesh (`t`, `c`; `first`: first_patches
/// of t in `plans`) instead of an index over every patch: the patches of the faces whose plans read the vertices
/// (faces_reading) that read one of the points, and the patches around those whose records name them.
/// For an edit of a few vertices after a change of topology, which an index would cost more than.
std::vector<int> patches_changed_near(const PolygonTopology& t, const MeshConnectivity& c, const PatchPlans& plans,
                                      const std::vector<int>& first, int first_row, const std::vector<int>& vertices,
                                      const std::vector<int>& rows);

}  // namespace gps
