#include "render/gl/point_precision.h"

#include <Eigen/Eigenvalues>
#include <algorithm>

#include "core/mesh/mesh_connectivity.h"

namespace gps {

bool needs_double_points(const Mat3& sigma) {
  const Vec3 values = Eigen::SelfAdjointEigenSolver<Mat3>().computeDirect(sigma, Eigen::EigenvaluesOnly).eigenvalues();
  return !(values.minCoeff() > 0.0) || values.maxCoeff() > kDoublePointsCondition * values.minCoeff();
}

// The need of the vertices listed (or of every vertex where `vertices` is null), on all cores.
void MeshPointPrecision::assess(const FramedGaussians& gaussians, const std::vector<int>* vertices) {
  const long long n = vertices ? (long long)vertices->size() : (long long)gaussians.n_vertices();
#pragma omp parallel for schedule(static) if (n >= kParallelFaces)
  for (long long i = 0; i < n; ++i) {
    const size_t v = vertices ? size_t((*vertices)[size_t(i)]) : size_t(i);
    thin_[v] = needs_double_points(gaussians.covariance(v)) ? 1 : 0;
  }
  thin_count_ = size_t(std::count(thin_.begin(), thin_.end(), char(1)));
}

MeshPointPrecision::MeshPointPrecision(const FramedGaussians& gaussians) : thin_(gaussians.n_vertices(), 0) {
  assess(gaussians, nullptr);
}

MeshPointPrecision::MeshPointPrecision(const MeshPointPrecision& before, const FramedGaussians& gaussians,
                                       const std::vector<int>& origin, const std::vector<int>& changed)
    : thin_(gaussians.n_vertices(), 0) {
  for (size_t v = 0; v < thin_.size(); ++v) {
    const size_t o = origin.empty() ? v : size_t(origin[v]);  // −1: a new vertex, among the changed
    if (o < before.thin_.size()) thin_[v] = before.thin_[o];
  }
  assess(gaussians, &changed);
}

MeshPointPrecision::MeshPointPrecision(const MeshPointPrecision& before, const GaussiansChange& change,
                                       const std::vector<int>& origin)
    : thin_(before.thin_) {
  const size_t n_before = thin_.size();
  thin_.resize(change.n_vertices, 0);
  for (size_t v = n_before; v < thin_.size(); ++v)  // a new vertex that did not change: its origin's
    if (const size_t o = origin.empty() ? v : size_t(origin[v]); o < n_before) thin_[v] = thin_[o];
  const long long n = (long long)change.changed.size();
#pragma omp parallel for schedule(static) if (n >= kParallelFaces)
  for (long long i = 0; i < n; ++i)
    thin_[size_t(change.changed[size_t(i)])] = needs_double_points(change.covariances[size_t(i)]) ? 1 : 0;
  thin_count_ = size_t(std::count(thin_.begin(), thin_.end(), char(1)));
}

void MeshPointPrecision::update(const FramedGaussians& gaussians, const std::vector<int>& changed) {
  if (changed.size() >= size_t(kParallelFaces)) return assess(gaussians, &changed);
  for (const int v : changed) {
    const char thin = needs_double_points(gaussians.covariance(size_t(v))) ? 1 : 0;
    thin_count_ = thin_count_ - size_t(thin_[size_t(v)]) + size_t(thin);
    thin_[size_t(v)] = thin;
  }
}

std::vector<ShaderStage> at_precision(std::vector<ShaderStage> stages, PointPrecision precision) {
  if (precision == PointPrecision::double_float)
    for (ShaderStage& stage : stages) stage.sources.insert(stage.sources.begin(), "#define GPS_DOUBLE\n");
  return stages;
}

}  // namespace gps
