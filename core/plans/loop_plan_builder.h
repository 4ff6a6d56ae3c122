#pragma once
// Subdivision plans of a triangle mesh under Loop GPS (docs/design.md §2, "Triangle meshes: Loop").
#include "core/reference/loop.h"
#include "core/plans/plan_builder.h"

namespace gps {

struct RangePlans;                  // core/plans/range_plans.h
class LoopExtraordinaryTableCache;  // core/extraordinary/loop_extraordinary_tables.h

/// One plan per triangle (patch p = face p, corners in face order at (u, v) = (0,0), (1,0), (0,1)):
/// a regular triangle (every corner regular: interior of valence 6 or on a boundary with 3 faces) is
/// one box-spline node; any other is split once, which leaves at most one irregular corner per
/// child: that child is an extraordinary node, evaluated exactly (core/extraordinary/loop_extraordinary_tables.h), the
/// others are box splines. Depth therefore does not trade accuracy: the plans are exact at depth 1. Throws gps::Error
/// naming the first face that is not a triangle, or a vertex of more than kMaxLoopValence faces.
/// With creases or corners, core/plans/loop_crease_plan_builder.h builds them. `connectivity`: the
/// topology's where the caller holds it; null: built here.
SurfaceTables build_loop_plans(const PolygonTopology& topology, LoopBeta beta, const Sharpness& sharpness = {},
                               const MeshConnectivity* connectivity = nullptr);

/// The plans of faces [first, last) of a smooth mesh (no sharpness) that passed build_loop_plans' checks,
/// for merge_ranges (core/plans/range_plans.h); exact tables come from `tables`, which ranges may share.
RangePlans build_loop_range(const PolygonTopology& topology, const MeshConnectivity& connectivity, int first, int last,
                            LoopBeta beta, LoopExtraordinaryTableCache& tables);

/// build_loop_plans' checks of the topology; throws as it does. `connectivity`: the topology's where
/// the caller holds it; null: built here.
void check_loop_plans(const PolygonTopology& topology, const MeshConnectivity* connectivity = nullptr);

/// The largest valence the exact tables take (their size grows with it).
inline constexpr int kMaxLoopValence = 64;

}  // namespace gps
