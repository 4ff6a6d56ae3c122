#include "ui/editing/covariance_brush.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "core/modelling/affine_transform.h"
#include "ui/editing/covariance_presets.h"

namespace gps {

double brush_weight(double distance, double radius, double strength) {
  if (!(radius > 0) || !(distance < radius)) return 0.0;
  const double x = distance / radius, f = 1.0 - x * x;
  return std::clamp(strength, 0.0, 1.0) * f * f;
}

Mat3 brushed_covariance(const Mat3& covariance, const Vec3& normal, double weight, BrushKind kind) {
  const double w = std::clamp(weight, 0.0, 1.0);
  if (kind == BrushKind::soften) {
    const double sigma = mean_sigma(covariance);
    return (1.0 - w) * covariance + w * sigma * sigma * Mat3::Identity();
  }
  const Mat3 a = Mat3::Identity() - w * (1.0 - kSharpenKeeps) * normal * normal.transpose();
  const Mat3 flattened = a * covariance * a.transpose();
  const Eigen::SelfAdjointEigenSolver<Mat3> eigen(0.5 * (flattened + flattened.transpose()));
  Vec3 values = eigen.eigenvalues();
  const double floor = kFlattestStretch * kFlattestStretch * values.maxCoeff();
  if (values.minCoeff() >= floor) return flattened;
  values = values.cwiseMax(floor);
  return eigen.eigenvectors() * values.asDiagonal() * eigen.eigenvectors().transpose();
}

std::vector<BrushedVertex> brush_reach(const CovarianceMesh& mesh, const Vec3& centre, double radius, double strength) {
  std::vector<BrushedVertex> reached;
  for (size_t v = 0; v < mesh.n_vertices(); ++v) {
    const double w = brush_weight((mesh.mean(v) - centre).norm(), radius, strength);
    if (w > 0) reached.push_back({int(v), w});
  }
  return reached;
}

}  // namespace gps
