#pragma once
// Covariances for a plain mesh (GPS paper Eq. 16–17, docs/design.md §1).
#include "core/mesh/covariance_mesh.h"

namespace gps {

/// Per face the second central moment of its vertices plus bias·λmax·I (Eq. 16); per vertex
/// Σ⁻¹ = Σ_f Σ_f⁻¹ over its faces (Eq. 17). Replaces every covariance of `mesh`; a vertex in no
/// face gets σ = half the mean edge length, isotropic. A face whose vertices coincide is refused, named
/// by `names`, and so is a mesh whose mean edge length lies outside [1e-45, 1e45] (its covariances
/// would pass covariance_problem's range), with the mesh unchanged.
void infer_covariances(CovarianceMesh& mesh, double bias = 0.05, const ElementNames& names = {});

/// Isotropic covariances whose deviation follows the local edge length: Σ_i = (s·l̄_i)²·I with l̄_i
/// the mean length of the edges at vertex i (an isolated vertex takes the mesh's mean edge length).
/// Refuses a mesh of edges outside [1e-45, 1e45] as infer_covariances does.
void isotropic_covariances(CovarianceMesh& mesh, double s = 0.5);

}  // namespace gps
