#pragma once
// A mesh with its plans, stencils and evaluated plan points, for tests of the plans.
#include "core/dual_map.h"
#include "core/plan_builder.h"
#include "core/samples.h"
#include "core/stencil_table.h"

namespace gps::test {

struct PlannedMesh {
  CovarianceMesh mesh;
  PlanTables tables;
  std::vector<Dual> base, points;

  PlannedMesh(CovarianceMesh m, int depth) : mesh(std::move(m)), tables(build_plans(topology_of(mesh.mesh), depth)) {
    base.resize(mesh.n_vertices());
    for (size_t i = 0; i < base.size(); ++i) base[i] = to_dual(mesh.mean(i), mesh.covariance(i));
    points = apply_stencils(tables.stencils, base);
  }
};

}  // namespace gps::test
