#pragma once
// The inspector's covariance presets: isotropic, a flat disc or a needle along the surface normal,
// sharpen and soften, and the covariance inferred from the mesh (GPS paper Eq. 16–17).
#include <vector>

#include "core/mesh/covariance_mesh.h"

namespace gps {

enum class CovariancePreset { isotropic, disc, needle, sharpen, soften, inferred };

/// The unit normal of the base mesh at a vertex: the sum of its faces' (Newell) area vectors;
/// +z for a vertex in no face or with a degenerate fan.
Vec3 vertex_normal(const CovarianceMesh& mesh, int vertex);

/// The geometric mean of a covariance's three standard deviations (the σ of the isotropic
/// Gaussian with the same volume).
double mean_sigma(const Mat3& covariance);

/// Thin direction of the disc and the needle: 1/10 of σ, as in Preiner's plateau cone (variances 1e-3 vs 1e-5).
constexpr double kFlatRatio = 0.1;

/// New covariances for `vertices` under `preset`. `sigma` is the isotropic preset's σ; the disc
/// and needle keep each vertex's mean_sigma() (σ in the wide directions, kFlatRatio·σ in the thin
/// ones; the disc is thin along the normal, the needle long along it); sharpen scales Σ by 0.1,
/// soften by 10; inferred recomputes Eq. 16–17 from the current means (bias 0.05).
std::vector<Mat3> preset_covariances(const CovarianceMesh& mesh, const std::vector<int>& vertices,
                                     CovariancePreset preset, double sigma);

}  // namespace gps
