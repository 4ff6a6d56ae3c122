#pragma once
// The planned surface of a covariance mesh (docs/design.md §2): its plan and stencil tables, built once
// per topology by the scheme that fits the mesh, and the 9D plan points, kept up to date by edits.
// The renderer uploads these tables as they are (as OpenSubdiv's Osd takes Far's tables).
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "core/reference/loop.h"
#include "core/plans/plan_builder.h"
#include "core/reference/reference_subdivision.h"
#include "core/plans/stencil_table.h"

namespace gps {

/// The depth of exact Catmull-Clark plans unless asked otherwise: the depth trades stencil rows for
/// cheaper evaluation, and this one renders fastest at equal exactness (gpsurf bench --render --depth N).
constexpr int kExactPlanDepth = 2;

struct PlanOptions {
  std::optional<Scheme> scheme;  // empty: Loop for a mesh of triangles only (valences up to
                                 // kMaxLoopValence), else Catmull-Clark
  int depth = kExactPlanDepth;  // Catmull-Clark: where exact nodes take over (0..8), or the thesis' Bézier plans (1..8)
  LoopBeta loop_beta = LoopBeta::loop;
  bool exact = true;  // Catmull-Clark: extraordinary vertices evaluated exactly (Loop's always are)
  bool operator==(const PlanOptions&) const = default;
};

/// The options the command line and Python name: scheme "auto" | "loop" | "catmull-clark", loop_beta
/// "loop" | "warren", depth −1 for the default, approximate for the thesis' Bézier plans. Throws a usage
/// error for an unknown name or a depth out of range.
PlanOptions plan_options_named(const std::string& scheme, const std::string& loop_beta, int depth = -1,
                               bool approximate = false);

/// The scheme `options` give for this mesh. `connectivity`: the topology's where the caller holds it (its
/// vertices' rows count their faces); null: counted here.
Scheme scheme_for(const PolygonTopology& topology, const PlanOptions& options,
                  const MeshConnectivity* connectivity = nullptr);

/// Plans and stencils of the mesh under its scheme (core/plans/plan_builder.h, core/plans/loop_plan_builder.h),
/// with its creases and corners.
SurfaceTables build_surface_plans(const PolygonTopology& topology, const PlanOptions& options,
                                  const Sharpness& sharpness = {});
/// The same of a covariance mesh, reading the connectivity it holds.
SurfaceTables build_surface_plans(const CovarianceMesh& mesh, const PlanOptions& options);

class PlannedSurface {
public:
  PlannedSurface(const CovarianceMesh& mesh, const PlanOptions& options);
  /// The mesh with tables already planned for it under `scheme` (core/plans/surface_replanner.h).
  PlannedSurface(const CovarianceMesh& mesh, Scheme scheme, SurfaceTables tables);

  Scheme scheme() const { return scheme_; }
  const SurfaceTables& tables() const { return tables_; }
  /// The tables, moved out (for a consumer that keeps them and computes its own points).
  SurfaceTables release_tables() && { return std::move(tables_); }
  /// Every plan point: the base vertices' q, then the stencil rows, of the mesh moved by −origin()
  /// (core/evaluation/surface_samples.h moves what they evaluate to back). The rows are computed on the
  /// first call (the renderer, which computes its own on the GPU, never asks); safe from several threads.
  const std::vector<Dual>& points() const;
  /// The mesh's evaluation_origin when planned (core/mesh/covariance_mesh.h): the points are about it.
  const Vec3& origin() const { return origin_; }
  /// After an edit of `changed` vertices of `mesh`: their q and, once computed, the rows that read them.
  void update(const CovarianceMesh& mesh, const std::vector<int>& changed);
  /// The stencil rows that read any of `vertices`, sorted, without repeats.
  std::vector<int> rows_reading(const std::vector<int>& vertices) const;

private:
  Scheme scheme_;
  Vec3 origin_ = Vec3::Zero();
  SurfaceTables tables_;
  StencilDependents dependents_;
  /// The base vertices' q, followed by the stencil rows once `rows_computed_`.
  mutable std::vector<Dual> points_;
  mutable bool rows_computed_ = false;
  /// Guards the rows' first computation; shared by copies, which is only coarser.
  std::shared_ptr<std::mutex> points_lock_ = std::make_shared<std::mutex>();
};

}  // namespace gps
