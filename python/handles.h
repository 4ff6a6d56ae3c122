#pragma once
// What Python's gpsurf.Mesh and gpsurf.Surface hold: shared, immutable snapshots. An assignment to
// a Mesh's attribute replaces its snapshot, and a Surface's update works on a copy while a snapshot
// is still read elsewhere, so a call running in the background (python/background_call.h) keeps
// reading what it was given.
#include <memory>

#include "core/mesh/covariance_mesh.h"
#include "core/plans/planned_surface.h"

namespace gps::python {

/// gpsurf.Mesh.
struct MeshHandle {
  std::shared_ptr<const CovarianceMesh> mesh;
};

/// A MeshHandle of `mesh`.
inline MeshHandle hold(CovarianceMesh&& mesh) { return {std::make_shared<const CovarianceMesh>(std::move(mesh))}; }

/// gpsurf.Surface: the plans of a mesh, the mesh they were made or last updated for, and their options.
struct SurfaceHandle {
  std::shared_ptr<PlannedSurface> surface;
  std::shared_ptr<const CovarianceMesh> mesh;
  PlanOptions options;
};

/// The surface of `mesh` planned under `options` (in the calling thread).
SurfaceHandle plan_surface(std::shared_ptr<const CovarianceMesh> mesh, const PlanOptions& options);

}  // namespace gps::python
