#pragma once
// A mesh with its plans, stencils and evaluated plan points, for tests of the plans.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/mesh/dual_map.h"
#include "core/evaluation/patch_eval.h"
#include "core/reference/reference_subdivision.h"
#include "core/plans/plan_builder.h"
#include "core/plans/planned_surface.h"
#include "core/modelling/samples.h"
#include "core/plans/stencil_table.h"

namespace gps::test {

struct PlannedMesh {
  CovarianceMesh mesh;
  SurfaceTables tables;
  std::vector<Dual> base, points;

  PlannedMesh(CovarianceMesh m, const PlanOptions& options)
      : mesh(std::move(m)),
        tables(build_surface_plans(mesh.topology(), options, mesh.sharpness)),
        base(base_points(mesh)) {
    points = apply_stencils(tables.stencils, base);
  }
  /// The thesis' approximate Catmull-Clark plans of the given depth (Bézier patches at extraordinary vertices).
  PlannedMesh(CovarianceMesh m, int depth)
      : PlannedMesh(std::move(m), PlanOptions{Scheme::catmull_clark, depth, LoopBeta::loop, false}) {}
};

/// Largest distance, relative to the bounding-box diagonal, between the plans at each reference
/// vertex's parameter and that vertex (GPS subdivision as `reference` says, with limit projection).
inline double error_against_reference(const PlannedMesh& p, const SubdivisionOptions& reference) {
  const auto ref = subdivide(p.mesh, reference);
  const double diag = bounding_box_diagonal(p.mesh);
  double worst = 0;
  EXPECT_EQ(ref.vertex_params.size(), ref.mesh.n_vertices());
  for (size_t k = 0; k < ref.mesh.n_vertices(); ++k) {
    const PatchParam& pp = ref.vertex_params[k];
    const auto s = evaluate_patch(p.tables.plans, p.points, pp.patch, pp.u, pp.v);
    EXPECT_TRUE(s.has_value());
    if (s) worst = std::max(worst, (s->position - ref.mesh.mean(k)).norm() / diag);
  }
  return worst;
}

}  // namespace gps::test
