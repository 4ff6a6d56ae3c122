#pragma once
// Subdivision plans of a triangle mesh with creases and corners under Loop GPS (docs/design.md §2
// "Creases and corners in the plans"): the crease rules refine pieces of the mesh level by level.
#include "core/mesh/sharpness.h"
#include "core/plans/plan_builder.h"
#include "core/reference/loop.h"

namespace gps {

struct LocalMesh;         // core/patches/local_mesh.h
struct RangePlans;        // core/plans/range_plans.h
class LoopCreaseTables;  // core/extraordinary/loop_crease_tables.h

/// One plan per triangle, as build_loop_plans lays them out: a triangle whose corners are regular
/// (core/patches/triangle_sectors.h) is one box-spline node, folded beyond infinitely sharp creases as
/// beyond a boundary; one with a single irregular corner whose neighbourhood is self-similar is an
/// exact node (core/extraordinary/loop_crease_tables.h); any other is split, so semi-sharp creases
/// refine until their sharpness has decayed. The topology must have passed build_loop_plans' checks.
/// `connectivity`: the topology's where the caller holds it; null: built here.
SurfaceTables build_creased_loop_plans(const PolygonTopology& topology, LoopBeta beta, const Sharpness& sharpness,
                                       const MeshConnectivity* connectivity = nullptr);

/// The plans of faces [first, last) of `base` (base_local_mesh of the topology and its sharpness), for
/// merge_ranges (core/plans/range_plans.h); exact tables come from `tables`, which ranges may share.
RangePlans build_creased_loop_range(const LocalMesh& base, int first, int last, LoopBeta beta,
                                    LoopCreaseTables& tables);

}  // namespace gps
