#include "bench/preprocess_figures.h"

#include "bench/median_timing.h"
#include "core/mesh/dual_map.h"
#include "core/modelling/samples.h"
#include "core/plans/stencil_table.h"

namespace gps {

nlohmann::json preprocess_figures(const std::string& name, int size, const PlanOptions& options) {
  const CovarianceMesh mesh = make_sample(name, size);
  const PolygonTopology& topology = mesh.topology();
  SurfaceTables tables;
  const double preprocess = median_seconds([&] { tables = build_surface_plans(topology, options); });
  std::vector<Dual> q = base_points(mesh);
  std::vector<Dual> points;
  const double apply = median_seconds([&] { points = apply_stencils(tables.stencils, q); });
  const StencilDependents deps = stencil_dependents(tables.stencils);
  const std::vector<int> one_vertex = {int(mesh.n_vertices() / 2)};
  const double update = median_seconds([&] { update_stencils(tables.stencils, deps, one_vertex, points); });
  const double dual_map = median_seconds([&] { q = base_points(mesh); });
  return {{"mesh", name + (size ? "/" + std::to_string(size) : "")},
          {"faces", mesh.n_faces()},
          {"patches", tables.plans.n_patches()},
          {"scheme", tables.plans.shape == PatchShape::triangle ? "loop" : "catmull-clark"},
          {"depth", tables.plans.max_depth},
          {"nodes_ints", tables.plans.nodes.size()},
          {"table_bytes_per_face", double(tables.bytes()) / double(mesh.n_faces())},
          {"stencil_rows", tables.stencils.n_rows()},
          {"stencil_nonzeros", tables.stencils.indices.size()},
          {"preprocess_ms", preprocess * 1e3},
          {"preprocess_us_per_face", preprocess * 1e6 / double(mesh.n_faces())},
          {"dual_map_ms", dual_map * 1e3},
          {"stencil_apply_ms", apply * 1e3},
          {"stencil_update_one_vertex_us", update * 1e6}};
}

}  // namespace gps
