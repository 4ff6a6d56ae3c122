#pragma once
// Moving, scaling and rotating vertices by an affine map x ↦ Ax + t. A Gaussian is carried along
// exactly (μ′ = Aμ + t, Σ′ = AΣAᵀ), and GPS commutes with affine maps: the 9D map F sends the pushed
// Gaussians to a linear image of the old 9D points, so every subdivision step and the limit surface
// move exactly with the vertices (docs/design.md §1).
#include <vector>

#include "core/mesh/dual_map.h"
#include "core/modelling/mesh_arrays.h"

namespace gps {

struct AffineMap {
  Mat3 linear = Mat3::Identity();
  Vec3 translation = Vec3::Zero();

  /// The map that applies `linear` about `pivot` (the pivot stays where it is).
  static AffineMap about(const Vec3& pivot, const Mat3& linear);
  /// From a row-major 4×4 matrix whose last row is (0, 0, 0, 1); throws gps::Error otherwise.
  static AffineMap from_rows(const std::vector<double>& rows);

  Vec3 apply(const Vec3& point) const { return linear * point + translation; }
  Gaussian apply(const Gaussian& g) const;
};

/// The vertices `vertices` (all of them when empty) carried by `map`. Refuses a map whose linear
/// part is singular or not finite (it would flatten the Gaussians) and results outside the ranges
/// a covariance mesh accepts.
Modelled transform_vertices(const CovarianceMesh& mesh, const std::vector<int>& vertices, const AffineMap& map);

}  // namespace gps
