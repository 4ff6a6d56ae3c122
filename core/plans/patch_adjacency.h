#pragma once
// Which patch lies across each patch edge, and which patch owns each patch corner: what the
// tessellation evaluation shaders need to evaluate every point of a shared edge or corner from one
// canonical patch at one parameter, so that neighbours generate bit-identical vertices there
// (shaders/canonical_edge.glsl). Built from the plan table alone, once per topology or, after a
// change, for the patches it reached (update_patch_adjacency).
//
// PatchPlans::patch_neighbours holds 4 ints per patch edge, at 4·(corners·patch + k): edge k runs
// from patch corner k to corner k+1 (quads: PatchPlans::patch_edges; triangles: the corner points).
//   [0] the patch across the edge, or −1 (a mesh boundary); for a quad edge whole_beside_halves,
//       the half-size patch at the edge's `from` end;
//   [1] that patch's edge index m, plus kNeighbourReversed (4) if it runs the other way, plus
//       kNeighbourSharpEdge (8) if the edge lies on an infinitely sharp crease; or −1;
//   [2], [3] likewise for the half-size patch at the `to` end of a whole_beside_halves edge, else −1.
// PatchPlans::corner_owners holds 2 ints per patch corner, at 2·(corners·patch + c): the lowest
// patch with the same corner point (PatchPlans::patch_corner_points) and its corner index there,
// plus kOwnerSharpCorner (4) where the patches around the corner have normals of their own there.
// The flag constants are in core/patches/patch_basis.h (shared with the shaders); readers mask them.
//
// Canonical rules (the shader's, tested in tests/core/test_patch_adjacency.cpp): a point inside a
// shared edge is evaluated by the lower-numbered patch of two whole (or two half) edges, and by the
// half-size patch where a whole quad edge meets two halves; a corner by its owner. On an infinitely
// sharp crease (docs/design.md, "Creases and corners in the plans") the surface is shared but each
// side has its own normal: a point on a flagged edge or corner takes its position from the
// canonical patch and its normal from the patch that draws it.
#include <cstdint>
#include <optional>
#include <vector>

#include "core/mesh/mesh_connectivity.h"
#include "core/mesh/sharpness.h"
#include "core/plans/kept_patches.h"
#include "core/plans/patch_plans.h"

namespace gps {

/// Fills plans.patch_neighbours and plans.corner_owners (see above) for plans built from `topology`
/// (whose vertices are the plans' first points) with `sharpness`. Linear in the number of patches.
/// A patch edge is sharp where it lies on an infinitely sharp edge between two faces; a patch corner
/// where the surface has no one tangent plane: at a base vertex with infinite corner sharpness, or
/// with two infinitely sharp edges or more (a boundary's edges counted) of which one lies between
/// two faces (a dart's single crease ends in a smooth point), and at a split face's edge point on a
/// sharp edge.
/// `connectivity`: the topology's where the caller keeps it (else built where the sharpness needs it).
void add_patch_adjacency(PatchPlans& plans, const PolygonTopology& topology, const Sharpness& sharpness,
                         const MeshConnectivity* connectivity = nullptr);

/// add_patch_adjacency for plans that keep most patches of plans whose patch_neighbours were
/// `old_neighbours` (`new_of_old`: per old patch, its number now, −1 gone; the kept patches' edges
/// and corner points renumbered alike): a kept patch edge keeps its record, renumbered, unless the
/// patch beside it is gone or a new patch now has the edge; those and the new patches' edges are
/// linked again. The same records as add_patch_adjacency, at the cost of the new patches and their
/// neighbours (the corner owners are found again whole, in one pass). False, changing nothing, with
/// infinitely sharp creases, whose flags it does not follow.
bool update_patch_adjacency(PatchPlans& plans, const Sharpness& sharpness, const std::vector<int32_t>& old_neighbours,
                            const std::vector<int>& new_of_old);

/// What making a plan's adjacency records changed of those of the plans before (update_patch_adjacency),
/// kept for the update after it.
struct AdjacencyWrites {
  /// Every kept patch kept its number: then `written` lists (ascending) the patches whose edge records
  /// were written, the new ones and those linked again, and every other record is the one before.
  bool numbers_kept = false;
  std::vector<int> written;
  /// The edge records with no patch across (a boundary, or a degenerate edge): patch · corners + k,
  /// ascending.
  std::vector<int> boundary;
  /// Where the numbers are kept: the patches whose corner owners were written (ascending), where known.
  std::optional<std::vector<int>> owners_written;
};

/// The edge records of `plans` with no patch across (AdjacencyWrites::boundary), from a pass over all:
/// what a whole build (add_patch_adjacency) tells the update after it.
std::vector<int> boundary_records(const PatchPlans& plans);

/// update_patch_adjacency from the plans before (`old`), with the kept patches in runs (`kept`,
/// increasing in both numberings), telling what it wrote (`writes`). Where every run keeps its numbers
/// and plans' patch_neighbours and corner_owners hold on entry the records of the plans that `old` was
/// made from by an update that told `held` (its numbers kept too), only the edge records the two
/// updates wrote, the boundary's and those beside patches that are gone are made again, and the owners
/// of the corners whose point a new or a gone patch has: the rest hold already. The same records
/// either way. `connectivity`: the base mesh's, from which the sharp flags of the records made again are
/// found (a kept record keeps its flags: its edge's crease and its corners' vertices did not change).
bool update_patch_adjacency(PatchPlans& plans, const Sharpness& sharpness, const MeshConnectivity& connectivity,
                            const PatchPlans& old, const std::vector<KeptPatches>& kept, const AdjacencyWrites* held,
                            AdjacencyWrites& writes);

struct EdgeNeighbour {
  int patch = -1;  // −1: none
  int edge = -1;
  bool reversed = false;
  bool sharp = false;  // the edge lies on an infinitely sharp crease
};

/// Entry `which` (0 or 1) of patch edge k's record.
inline EdgeNeighbour edge_neighbour(const PatchPlans& plans, int patch, int k, int which = 0) {
  const int32_t* r = &plans.patch_neighbours[size_t(4 * (plans.corners() * patch + k) + 2 * which)];
  if (r[0] < 0) return {};
  return {r[0], r[1] & kNeighbourEdgeMask, (r[1] & kNeighbourReversed) != 0, (r[1] & kNeighbourSharpEdge) != 0};
}

struct CornerOwner {
  int patch = -1;
  int corner = -1;
  bool sharp = false;  // the patches around the corner have normals of their own there
};

/// Patch corner c's record.
inline CornerOwner corner_owner(const PatchPlans& plans, int patch, int c) {
  const int32_t* r = &plans.corner_owners[size_t(2 * (plans.corners() * patch + c))];
  return {r[0], r[1] & kOwnerCornerMask, (r[1] & kOwnerSharpCorner) != 0};
}

/// A patch edge: patch and edge index.
struct PatchEdgeSlot {
  int patch = -1;
  int edge = -1;
  bool operator==(const PatchEdgeSlot&) const = default;
};

/// The patch edge that names the limit curve patch edge k lies on, for both sides alike
/// (shaders/canonical_edge.glsl, curve_edge): of a whole edge beside two half-size patches, that edge,
/// and of each half beside it, the same; of a whole edge, and of a half beside another half or on the
/// boundary, the lower of the two sides. The corner pass keeps the curve's midpoint at its slot.
PatchEdgeSlot curve_edge(const PatchPlans& plans, int patch, int k);

/// Whether the corner pass evaluates patch corner c's limit at the corner's own slot: at its owner,
/// and at every patch around a corner whose patches have normals of their own.
inline bool evaluates_corner(const PatchPlans& plans, int patch, int c) {
  const CornerOwner owner = corner_owner(plans, patch, c);
  return (owner.patch == patch && owner.corner == c) || owner.sharp;
}

}  // namespace gps
