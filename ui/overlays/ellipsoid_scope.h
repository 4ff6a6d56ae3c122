#pragma once
// Whose covariance ellipsoids the editor draws: all of them, or those of the selection and its
// neighbours (the vertices sharing an edge with a selected one), so that a dense mesh's ellipsoids
// are not a tangle of lines. "Automatic" draws all of them up to kAllEllipsoidsUpTo vertices.
#include <cstddef>
#include <vector>

#include "core/mesh/covariance_mesh.h"

namespace gps {

inline constexpr size_t kAllEllipsoidsUpTo = 1000;

enum class EllipsoidScope { automatic = 0, neighbourhood = 1, all = 2 };

/// Whether every vertex's ellipsoid is drawn under `scope` for a mesh of `n_vertices`.
bool all_ellipsoids(EllipsoidScope scope, size_t n_vertices);

/// The selected vertices and every vertex sharing an edge with one of them, ascending, once each.
std::vector<int> selection_neighbourhood(const CovarianceMesh& mesh, const std::vector<int>& selected);

}  // namespace gps
