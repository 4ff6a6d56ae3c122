#pragma once
// The sharpen/soften brush: the GPS paper's use of covariances as a modelling tool, painted. Each dab
// changes the Gaussians of the vertices near a point of the surface, weighted by a smooth falloff:
// sharpen flattens them along the surface normal (a flat spot, a crisper edge where dabs meet), soften
// makes them round again.
#include <vector>

#include "core/mesh/covariance_mesh.h"

namespace gps {

enum class BrushKind { sharpen, soften };

/// What one full-weight sharpen dab keeps of a Gaussian's extent along the normal.
constexpr double kSharpenKeeps = 0.5;

/// The brush's weight at `distance` from its centre: strength · (1 − (d/r)²)² inside the radius, 0 outside.
double brush_weight(double distance, double radius, double strength);

/// The covariance a dab of weight w ∈ [0, 1] leaves: sharpen maps Σ by A = I − w (1 − kSharpenKeeps) n nᵀ
/// (Σ′ = AΣAᵀ: thinner along the unit normal n, the rest kept), its eigenvalues held at least
/// kFlattestStretch² of the largest (core/modelling/affine_transform.h's floor, relative to the
/// Gaussian, so that dabs never make it degenerate); soften blends toward the round Gaussian of the
/// same volume, Σ′ = (1 − w) Σ + w σ̄² I with σ̄ the geometric mean of its σs.
Mat3 brushed_covariance(const Mat3& covariance, const Vec3& normal, double weight, BrushKind kind);

/// A dab at `centre`: the vertices within `radius` of it and their weights (brush_weight), in vertex order.
struct BrushedVertex {
  int vertex;
  double weight;
};
std::vector<BrushedVertex> brush_reach(const CovarianceMesh& mesh, const Vec3& centre, double radius, double strength);

}  // namespace gps
