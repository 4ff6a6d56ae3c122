#pragma once
// Subdivision plans and their stencil table from a mesh's topology (thesis 2.3, docs/design.md §2).
#include "core/mesh/mesh_connectivity.h"
#include "core/mesh/sharpness.h"
#include "core/plans/patch_plans.h"

namespace gps {

struct LocalMesh;                   // core/patches/local_mesh.h
struct RangePlans;                  // core/plans/range_plans.h
class QuadExtraordinaryTableCache;  // core/extraordinary/quad_extraordinary_tables.h

struct SurfaceTables {
  PatchPlans plans;
  StencilTable stencils;

  /// The bytes the tables hold in the CPU's memory (ints, and doubles for weights and extraordinary tables).
  size_t bytes() const {
    const PatchPlans& p = plans;
    return 4 * (p.nodes.size() + p.patch_roots.size() + p.patch_corner_points.size() + p.patch_edges.size() +
                p.patch_neighbours.size() + p.corner_owners.size() + stencils.offsets.size() +
                stencils.indices.size()) +
           8 * (p.extraordinary_tables.size() + stencils.weights.size());
  }
};

/// How plans meet extraordinary and irregular boundary vertices.
enum class ExtraordinaryNodes {
  exact,   // refined down to the plan depth 0..8 (further where a node has more than one irregular
           // corner: one level, two below a split n-gon), then evaluated exactly there
           // (core/extraordinary/quad_extraordinary_tables.h); the depth trades stencil rows for cheaper evaluation
  bezier,  // the thesis' plans (2.3): refined down to the plan depth 1..8, then Bézier patches from
           // the rules of thesis Fig. 2.5, an approximation that closes in as the depth grows
};

/// Builds one plan per patch (core/plans/patch_layout.h numbering): quadtrees refined around
/// extraordinary and irregular boundary vertices, regular nodes as bicubic B-splines (boundary
/// phantoms p₋₁ = 2p₀ − p₁), the nodes at those vertices as `extraordinary` says down from
/// `max_depth` (an exact node that is still not self-similar at depth 8 would become a Bézier
/// patch; none is met in practice). Depends on topology and sharpness only: semi-sharp creases
/// and corners refine their nodes until the sharpness has decayed, infinitely sharp ones are cut edges
/// (core/patches/quad_nets.h, regular_corner) and part of the extraordinary tables' neighbourhoods. `bspline_leaves` =
/// false makes every regular node a terminal Bézier node instead (tests: with n = 4 the Fig. 2.5
/// rules are the B-spline's). `connectivity`: the topology's, where the caller holds it (a covariance
/// mesh's); null: built here.
SurfaceTables build_plans(const PolygonTopology& topology, int max_depth,
                          ExtraordinaryNodes extraordinary = ExtraordinaryNodes::exact, bool bspline_leaves = true,
                          const Sharpness& sharpness = {}, const MeshConnectivity* connectivity = nullptr);

/// The faces build_plans builds together (core/plans/range_plans.h; the tables do not depend on it).
inline constexpr int kFacesPerRange = 1024;

/// The most faces at a vertex, and sides of a face, that patch plans take. The plans read every
/// neighbour of an extraordinary vertex from each patch at it (thesis Fig. 2.5 corner rule), so their
/// stencils grow with the square of the valence (and of the face size, which becomes the valence of the
/// face's centre after the split): past this bound they would take minutes and gigabytes.
inline constexpr int kMaxPlanValence = 256;

/// build_plans' checks of the depth and the valences; throws as it does. `connectivity`: the topology's
/// where the caller holds it (its vertices' rows count their faces); null: counted here.
void check_quad_plans(const PolygonTopology& topology, int max_depth, ExtraordinaryNodes extraordinary,
                      const MeshConnectivity* connectivity = nullptr);

/// The plans of faces [first, last) of `base` (base_local_mesh of the topology and its sharpness), for
/// merge_ranges; extraordinary tables come from `cache`, which ranges built at once may share.
RangePlans build_quad_range(const LocalMesh& base, int first, int last, int max_depth,
                            ExtraordinaryNodes extraordinary, bool bspline_leaves, QuadExtraordinaryTableCache& cache);

}  // namespace gps
