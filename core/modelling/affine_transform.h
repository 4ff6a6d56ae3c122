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

/// The vertices `vertices` (all of them when empty) carried by `map`. A map that mirrors (negative
/// determinant) also reverses the faces of every connected part it moves whole, as Blender does, so
/// that the surface stays outward (signed volume kept positive). Refuses a map whose linear part is
/// not finite, singular or stretches one direction over 1e12 times another (it would flatten the
/// Gaussians), and results outside the ranges a covariance mesh accepts.
Modelled transform_vertices(const CovarianceMesh& mesh, const std::vector<int>& vertices, const AffineMap& map);

/// Reverses the corner order (keeping the first corner) of every face of each connected part whose
/// vertices all lie in `moved`: the orientation a mirror of those parts needs.
void reverse_parts_within(MeshArrays& arrays, const std::vector<int>& moved);

}  // namespace gps
