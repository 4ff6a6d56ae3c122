#pragma once
// A mesh with its plans, stencils and evaluated plan points, for tests of the plans.
#include "core/dual_map.h"
#include "core/plan_builder.h"
#include "core/planned_surface.h"
#include "core/samples.h"
#include "core/stencil_table.h"

namespace gps::test {

struct PlannedMesh {
  CovarianceMesh mesh;
  PlanTables tables;
  std::vector<Dual> base, points;

  PlannedMesh(CovarianceMesh m, const PlanOptions& options)
      : mesh(std::move(m)), tables(build_surface_plans(topology_of(mesh.mesh), options)), base(base_points(mesh)) {
    points = apply_stencils(tables.stencils, base);
  }
  /// The thesis' approximate Catmull-Clark plans of the given depth (Bézier patches at extraordinary vertices).
  PlannedMesh(CovarianceMesh m, int depth) : PlannedMesh(std::move(m), PlanOptions{Scheme::catmull_clark, depth, LoopBeta::loop, false}) {}
};

}  // namespace gps::test
