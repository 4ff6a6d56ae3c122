#pragma once
// Moving, scaling and rotating vertices by an affine map x ↦ Ax + t. A Gaussian is carried along
// exactly (μ′ = Aμ + t, Σ′ = AΣAᵀ) unless the map flattens it past a floor (carried_gaussian), and
// GPS commutes with affine maps: the 9D map F sends the pushed
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

/// How flat a map may make a Gaussian, as a ratio of the map's weakest stretch to its strongest; see
/// carried_gaussian.
inline constexpr double kFlattestStretch = 1e-3;

/// A Gaussian carried by a map, and whether its covariance had to be held at the floor.
struct CarriedGaussian {
  Gaussian gaussian;
  bool clamped = false;
};

/// `g` carried by `map` as the modelling operations and the editor's G / S / R carry it: the mean
/// exactly (μ′ = Aμ + t: a scale of 0 flattens the positions onto a plane, as in Blender) and the
/// covariance AΣAᵀ with its eigenvalues raised to at least (kFlattestStretch · σ_max(A))² · λ_min(Σ)
/// (σ_max(A) taken as 1 for the zero map). The floor is what a map whose weakest direction keeps
/// 1e-3 of its strongest does to the Gaussian's thinnest axis: relative to the Gaussian and to the
/// map, so a uniformly scaled mesh under the same map gives the same result scaled; every map within
/// that ratio is carried exactly (then the result is map.apply(g)); and the carried Gaussian's
/// condition number is at most 1e6 times its own, thin enough to draw the surface onto the plane
/// without the collapse a covariance of eigenvalue ~0 gives (its inverse then dominates every 9D
/// blend it enters, docs/design.md §1).
CarriedGaussian carried_gaussian(const AffineMap& map, const Gaussian& g);
/// The same with σ_max(A) given (strongest_stretch(map)), for many Gaussians under one map.
CarriedGaussian carried_gaussian(const AffineMap& map, const Gaussian& g, double strongest_stretch);
double strongest_stretch(const AffineMap& map);

/// The vertices `vertices` (all of them when empty) carried by `map` (carried_gaussian; the summary
/// says how many Gaussians were held at the floor). A map that mirrors (negative determinant) also
/// reverses the faces of every connected part it moves whole, as Blender does, so that the surface
/// stays outward (signed volume kept positive). Refuses a map that is not finite and results outside
/// the ranges a covariance mesh accepts.
Modelled transform_vertices(const CovarianceMesh& mesh, const std::vector<int>& vertices, const AffineMap& map);

/// The same on `mesh` itself, at the cost of the vertices moved where the map does not mirror (a
/// mirror rebuilds the mesh with its parts' faces reversed): returns the selection and sets
/// `summary`. Every moved Gaussian is checked before any changes, so a refusal changes nothing.
std::vector<int> transform_vertices_in_place(CovarianceMesh& mesh, const std::vector<int>& vertices,
                                             const AffineMap& map, std::string& summary);

/// Reverses the corner order (keeping the first corner) of every face of each connected part whose
/// vertices all lie in `moved`: the orientation a mirror of those parts needs. Returns how many faces.
int reverse_parts_within(MeshArrays& arrays, const std::vector<int>& moved);

}  // namespace gps
