#pragma once
// The precision the GPU keeps a mesh's plan points in (render/gl/gpu_layout.h, point_real): float,
// or double for a mesh with a Gaussian so thin (condition number of Σ past kDoublePointsCondition)
// that float sums of 9D points no longer hold Σ⁻¹'s thin directions (docs/design.md §2). Double
// points, sums and back map cost GPU time, and only such meshes pay it.
#include <cstddef>
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "render/gl/gaussians_change.h"
#include "render/gl/normalised_frame.h"
#include "render/gl/shader_program.h"

namespace gps {

enum class PointPrecision { single_float, double_float };

/// Condition numbers of Σ past which a mesh's points are kept in double: float's sums of Gaussians of
/// one orientation, which keep that condition, hold their thin directions to about 1 % up to it.
inline constexpr double kDoublePointsCondition = 2e5;

/// Whether a Gaussian of covariance `sigma` needs double points (not positive definite included).
bool needs_double_points(const Mat3& sigma);

/// The precision a mesh needs, kept up to date through edits at the cost of their changed vertices.
class MeshPointPrecision {
public:
  MeshPointPrecision() = default;
  explicit MeshPointPrecision(const FramedGaussians& gaussians);
  /// `before`'s after a change of topology: a vertex keeps its `origin`'s need unless it is among
  /// the `changed` (changed_gaussians, which new vertices are among; an empty `origin` keeps numbers).
  MeshPointPrecision(const MeshPointPrecision& before, const FramedGaussians& gaussians, const std::vector<int>& origin,
                     const std::vector<int>& changed);
  /// The same for a change that keeps vertex numbers, from its changed Gaussians (gaussians_change).
  MeshPointPrecision(const MeshPointPrecision& before, const GaussiansChange& change, const std::vector<int>& origin);
  /// The `changed` vertices' Gaussians again.
  void update(const FramedGaussians& gaussians, const std::vector<int>& changed);
  PointPrecision precision() const {
    return thin_count_ > 0 ? PointPrecision::double_float : PointPrecision::single_float;
  }

private:
  void assess(const FramedGaussians& gaussians, const std::vector<int>* vertices);

  std::vector<char> thin_;  // per vertex: needs double
  size_t thin_count_ = 0;
};

/// `stages` with GPS_DOUBLE defined ahead of every stage's sources for double points.
std::vector<ShaderStage> at_precision(std::vector<ShaderStage> stages, PointPrecision precision);

}  // namespace gps
