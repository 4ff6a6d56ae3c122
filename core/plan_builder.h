#pragma once
// Subdivision plans and their stencil table from a mesh's topology (thesis 2.3, DESIGN.md §2).
#include "core/mesh_connectivity.h"
#include "core/plan_table.h"

namespace gps {

struct PlanTables {
  PlanTable plans;
  StencilTable stencils;
};

/// How plans meet extraordinary and irregular boundary vertices.
enum class ExtraordinaryNodes {
  exact,   // a node with one irregular corner is evaluated exactly (core/quad_ev_tables.h); nodes
           // with more are split until they have one (one level, two below a split n-gon)
  bezier,  // the thesis' plans (2.3): refined down to the plan depth, then Bézier patches from the
           // rules of thesis Fig. 2.5, an approximation that closes in as the depth grows
};

/// Builds one plan per patch (core/patch_layout.h numbering): quadtrees refined around
/// extraordinary and irregular boundary vertices, regular nodes as bicubic B-splines (boundary
/// phantoms p₋₁ = 2p₀ − p₁), the nodes at those vertices as `extraordinary` says; `max_depth`
/// (1..8) bounds the refinement (exact nodes never need more than 2; beyond it a node that is
/// still not self-similar becomes a Bézier patch). Depends on topology only. `bspline_leaves` =
/// false makes every regular node a terminal Bézier node instead (tests: with n = 4 the Fig. 2.5
/// rules are the B-spline's).
PlanTables build_plans(const PolygonTopology& topology, int max_depth, ExtraordinaryNodes extraordinary = ExtraordinaryNodes::exact,
                       bool bspline_leaves = true);

}  // namespace gps
