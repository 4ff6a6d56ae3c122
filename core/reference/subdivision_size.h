#pragma once
// The size of a subdivision's result, known from the counts of its input before any work.
#include "core/mesh/covariance_mesh.h"
#include "core/reference/reference_subdivision.h"
#include "core/support/memory_budget.h"

namespace gps {

/// The vertices and faces `options.levels` steps of `options.scheme` make from `mesh` (exact:
/// Catmull-Clark turns an n-gon into n quads, then every quad into 4; Loop every triangle into 4),
/// and the memory subdivide() holds at its peak for them (a measured upper bound per vertex and
/// per face corner).
OutputSize subdivision_size(const CovarianceMesh& mesh, const SubdivisionOptions& options);

}  // namespace gps
