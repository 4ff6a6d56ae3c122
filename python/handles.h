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

  // pybind11 gives an instance Python made without __init__ (Mesh.__new__(Mesh)) its storage from
  // this operator new when a method first reads it: it then holds an empty mesh, not garbage. A
  // construction writes over it; the empty mesh is not owned, so nothing is left behind.
  static void* operator new(size_t size);
  static void operator delete(void* storage) { ::operator delete(storage); }
};

/// Whether `handle` holds what a construction made, not the empty mesh of one made without __init__
/// (held without ownership).
inline bool initialised(const MeshHandle& handle) { return handle.mesh.use_count() > 0; }

/// A MeshHandle of `mesh`.
inline MeshHandle hold(CovarianceMesh&& mesh) { return {std::make_shared<const CovarianceMesh>(std::move(mesh))}; }

/// gpsurf.Surface: the plans of a mesh, the mesh they were made or last updated for, and their options.
struct SurfaceHandle {
  std::shared_ptr<PlannedSurface> surface;
  std::shared_ptr<const CovarianceMesh> mesh;
  PlanOptions options;

  // As MeshHandle's: made without __init__, it holds the plans of an empty mesh.
  static void* operator new(size_t size);
  static void operator delete(void* storage) { ::operator delete(storage); }
};

/// As initialised(MeshHandle).
inline bool initialised(const SurfaceHandle& handle) { return handle.surface.use_count() > 0; }

/// The surface of `mesh` planned under `options` (in the calling thread).
SurfaceHandle plan_surface(std::shared_ptr<const CovarianceMesh> mesh, const PlanOptions& options);

}  // namespace gps::python
