#include "core/plans/planned_surface.h"

#include <algorithm>

#include "core/mesh/dual_map.h"
#include "core/support/error.h"
#include "core/plans/loop_plan_builder.h"
#include "core/plans/patch_adjacency.h"
#include "core/reference/reference_subdivision.h"

namespace gps {

PlanOptions plan_options_named(const std::string& scheme, const std::string& loop_beta, int depth, bool approximate) {
  PlanOptions o;
  if (scheme == "loop")
    o.scheme = Scheme::loop;
  else if (scheme == "catmull-clark")
    o.scheme = Scheme::catmull_clark;
  else if (scheme != "auto")
    throw usage_error("scheme must be auto, loop or catmull-clark, got '" + scheme + "'");
  if (loop_beta != "loop" && loop_beta != "warren")
    throw usage_error("loop-beta must be loop or warren, got '" + loop_beta + "'");
  o.loop_beta = loop_beta == "warren" ? LoopBeta::warren : LoopBeta::loop;
  o.exact = !approximate;
  if (approximate) o.depth = 3;  // the thesis' plans
  if (depth < -1) throw usage_error("depth must be 0..8, or -1 for the default, got " + std::to_string(depth));
  if (depth >= 0) o.depth = depth;
  if (o.depth < (approximate ? 1 : 0) || o.depth > 8)
    throw usage_error("depth must be " + std::string(approximate ? "1" : "0") + "..8, got " + std::to_string(depth));
  return o;
}

Scheme scheme_for(const PolygonTopology& topology, const PlanOptions& options, const MeshConnectivity* connectivity) {
  if (options.scheme) return *options.scheme;
  for (int f = 0; f < topology.n_faces(); ++f)
    if (topology.face_size(f) != 3) return Scheme::catmull_clark;
  // Loop's exact tables grow with the valence: past kMaxLoopValence faces at a vertex, Catmull-Clark.
  if (connectivity && connectivity->vertex_face_offsets.size() == size_t(topology.n_vertices) + 1) {
    for (int v = 0; v < topology.n_vertices; ++v)
      if (connectivity->n_vertex_faces(v) > kMaxLoopValence) return Scheme::catmull_clark;
    return topology.n_faces() > 0 ? Scheme::loop : Scheme::catmull_clark;
  }
  std::vector<int> faces_at(size_t(topology.n_vertices), 0);
  for (const int v : topology.verts)
    if (++faces_at[size_t(v)] > kMaxLoopValence) return Scheme::catmull_clark;
  return topology.n_faces() > 0 ? Scheme::loop : Scheme::catmull_clark;
}

namespace {

SurfaceTables plans_of(const PolygonTopology& topology, const MeshConnectivity& connectivity,
                       const PlanOptions& options, const Sharpness& sharpness) {
  const ExtraordinaryNodes extraordinary = options.exact ? ExtraordinaryNodes::exact : ExtraordinaryNodes::bezier;
  SurfaceTables tables = scheme_for(topology, options, &connectivity) == Scheme::loop
                             ? build_loop_plans(topology, options.loop_beta, sharpness, &connectivity)
                             : build_plans(topology, options.depth, extraordinary, true, sharpness, &connectivity);
  add_patch_adjacency(tables.plans, topology, sharpness, &connectivity);
  return tables;
}

}  // namespace

SurfaceTables build_surface_plans(const PolygonTopology& topology, const PlanOptions& options,
                                  const Sharpness& sharpness) {
  return plans_of(topology, connectivity_of(topology), options, sharpness);
}

SurfaceTables build_surface_plans(const CovarianceMesh& mesh, const PlanOptions& options) {
  return plans_of(mesh.topology(), mesh.connectivity(), options, mesh.sharpness);
}

PlannedSurface::PlannedSurface(const CovarianceMesh& mesh, const PlanOptions& options) {
  scheme_ = scheme_for(mesh.topology(), options, &mesh.connectivity());
  tables_ = build_surface_plans(mesh, options);
  dependents_ = stencil_dependents(tables_.stencils);
  origin_ = evaluation_origin(mesh);
  points_ = base_points(mesh, origin_);
}

PlannedSurface::PlannedSurface(const CovarianceMesh& mesh, Scheme scheme, SurfaceTables tables)
    : scheme_(scheme), tables_(std::move(tables)) {
  dependents_ = stencil_dependents(tables_.stencils);
  origin_ = evaluation_origin(mesh);
  points_ = base_points(mesh, origin_);
}

const std::vector<Dual>& PlannedSurface::points() const {
  const std::lock_guard<std::mutex> hold(*points_lock_);
  if (!rows_computed_) {
    points_ = apply_stencils(tables_.stencils, points_);
    rows_computed_ = true;
  }
  return points_;
}

void PlannedSurface::update(const CovarianceMesh& mesh, const std::vector<int>& changed) {
  const std::lock_guard<std::mutex> hold(*points_lock_);
  for (const int v : changed) points_[size_t(v)] = to_dual(mesh.mean(size_t(v)) - origin_, mesh.covariance(size_t(v)));
  if (rows_computed_) update_stencils(tables_.stencils, dependents_, changed, points_);
}

std::vector<int> PlannedSurface::rows_reading(const std::vector<int>& vertices) const {
  return gps::rows_reading(dependents_, vertices);
}

}  // namespace gps
