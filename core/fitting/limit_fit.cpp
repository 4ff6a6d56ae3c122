#include "core/fitting/limit_fit.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/IterativeLinearSolvers>

#include "core/fitting/block_jacobi_preconditioner.h"
#include "core/fitting/closest_points.h"
#include "core/fitting/limit_weights.h"
#include "core/fitting/precision_factor.h"
#include "core/mesh/dual_map.h"
#include "core/support/error.h"
#include "core/plans/stencil_table.h"

namespace gps {

namespace {

using Block = Eigen::Matrix<double, 9, 9>;

struct Parameters {
  std::vector<Vec3> means;
  std::vector<Vec6> factors;  // empty for a plain fit
};

// Per vertex: its precision K = LLᵀ and factor L.
struct VertexState {
  std::vector<Mat3> precision, factor;
};

// Per target, at the current parameters and correspondence: the limit point x, K(u, v)⁻¹ and x − p;
// with a normal term, the tangents x_u, x_v, the precision's derivatives K_u, K_v, the normal
// residual (the surface's unit normal m less its component along the target's normal n, scaled:
// its length is the sine of the angle between them) and its derivative by c = x_u × x_v.
struct PointState {
  Vec3 x, residual;
  Mat3 inverse;
  Vec3 tangent[2];
  Mat3 precision_derivative[2];
  Vec3 normal_residual = Vec3::Zero();
  Mat3 normal_gradient = Mat3::Zero();
};

// How a point's limit position x and its normal residual change with one vertex's unknowns.
struct PointJacobian {
  Eigen::Matrix<double, 3, 9> position;
  Eigen::Matrix<double, 3, 9> normal;
};

// The cross-product matrix [a]×: [a]× b = a × b.
Mat3 cross_matrix(const Vec3& a) {
  Mat3 m;
  m << 0, -a[2], a[1], a[2], 0, -a[0], -a[1], a[0], 0;
  return m;
}

// Throws where the points lie apart from the mesh, farther than the larger of the two is across: the
// fit pulls a surface onto points near it, and from so far it would stretch the mesh toward the
// points' near side, whose closest points all the points are.
void refuse_points_apart(const CovarianceMesh& mesh, const std::vector<Vec3>& targets) {
  Vec3 lo, hi, target_lo = targets.front(), target_hi = targets.front();
  bounding_box(mesh, lo, hi);
  for (const Vec3& p : targets) target_lo = target_lo.cwiseMin(p), target_hi = target_hi.cwiseMax(p);
  const Vec3 gap = (target_lo - hi).cwiseMax(lo - target_hi).cwiseMax(0.0);
  const double size = std::max((hi - lo).norm(), (target_hi - target_lo).norm());
  if (!(gap.norm() > size)) return;
  std::ostringstream said;
  said << "the points to fit lie " << gap.norm() << " from the mesh, " << std::max(1.0, std::round(gap.norm() / size))
       << " times their size: place the mesh over them first";
  throw Error(said.str());
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The fit's problem: unknowns P per vertex (3 means, then 6 factor parameters unless plain), vertex-major.
class FitProblem {
public:
  FitProblem(const CovarianceMesh& coarse, const std::vector<Vec3>& targets, const std::vector<Vec3>& normals,
             const FitOptions& options)
      : options_(options),
        targets_(targets),
        normals_(normals),
        surface_(options.plain ? with_isotropic_covariances(coarse) : coarse, options.plans),
        n_(int(coarse.n_vertices())),
        p_(options.plain ? 3 : 9) {
    const CovarianceMesh start = options.plain ? with_isotropic_covariances(coarse) : coarse;
    for (int i = 0; i < n_; ++i) {
      start_.means.push_back(start.mean(size_t(i)));
      if (!options.plain) start_.factors.push_back(factor_parameters(start.covariance(size_t(i)).inverse()));
    }
    plain_precision_ = start.covariance(0).inverse();
    diagonal_ = bounding_box_diagonal(targets);
    if (!(diagonal_ > 0)) diagonal_ = 1;
    // The umbrella Laplacian, and its normal matrix LᵀL that the smoothness term's Hessian is.
    std::vector<Eigen::Triplet<double>> lap;
    double edge_sum = 0;
    size_t edges = 0;
    const MeshConnectivity& c = coarse.connectivity();
    for (int i = 0; i < int(coarse.n_vertices()); ++i) {
      const double degree = double(coarse.valence(size_t(i)));
      lap.emplace_back(i, i, degree > 0 ? -1.0 : 0.0);
      double own_sum = 0;
      for (int k = c.vertex_edge_offsets[size_t(i)]; k < c.vertex_edge_offsets[size_t(i) + 1]; ++k) {
        const int w = c.other_vertex(c.vertex_edges[size_t(k)], i);
        lap.emplace_back(i, w, 1.0 / degree);
        own_sum += (start.mean(size_t(i)) - start.mean(size_t(w))).norm();
        ++edges;
      }
      edge_sum += own_sum;
      edge_.push_back(degree > 0 ? own_sum / degree : 0.0);
    }
    Eigen::SparseMatrix<double> l(n_, n_);
    l.setFromTriplets(lap.begin(), lap.end());
    laplacian_normal_ = Eigen::SparseMatrix<double>(l.transpose() * l);
    length_ = edges > 0 ? edge_sum / double(edges) : diagonal_;
    if (!options.plain && options.normal_weight > 0 && !normals.empty())
      normal_scale_ = std::sqrt(options.normal_weight) * length_;
    const double per_vertex = double(targets.size()) / double(std::max(n_, 1));
    smoothness_ = options.smoothness * per_vertex;
    covariance_smoothness_ =
        options.covariance_smoothness.value_or(normal_scale_ > 0 ? 0.0 : kPointsCovarianceSmoothness) * per_vertex;
    for (double& edge : edge_)
      if (!(edge > 0)) edge = length_;
    if (p_ == 9)
      for (int i = 0; i < n_; ++i) bound(i, start_.factors[size_t(i)]);
    if (p_ == 9 && options.covariance_prior > 0) set_prior(options.covariance_prior * per_vertex);
  }

  const Parameters& start() const { return start_; }
  int unknowns() const { return n_ * p_; }
  int unknowns_per_vertex() const { return p_; }
  /// Lowers the bound on the standard deviations to FitOptions::relaxed_min_sigma; false where it is
  /// lowered already or the fit has no second stage.
  bool relax_lower_bound() {
    if (relaxed_ || !fits_in_two_stages(options_)) return false;
    relaxed_ = true;
    return true;
  }
  bool relaxed() const { return relaxed_; }

  VertexState vertex_state(const Parameters& x) const {
    VertexState s;
    for (int i = 0; i < n_; ++i) {
      if (p_ == 3) {
        s.precision.push_back(plain_precision_);
        s.factor.push_back(Mat3::Identity());
      } else {
        s.factor.push_back(cholesky_factor(x.factors[size_t(i)]));
        s.precision.push_back(s.factor.back() * s.factor.back().transpose());
      }
    }
    return s;
  }

  std::vector<Dual> base_points(const Parameters& x, const VertexState& s) const {
    std::vector<Dual> q(static_cast<size_t>(n_));
    for (size_t i = 0; i < size_t(n_); ++i) q[i] << vech(s.precision[i]), s.precision[i] * x.means[i];
    return q;
  }

  // Closest points on the limit surface of `x`; each kept at the old one where that is closer.
  void update_correspondences(const Parameters& x) {
    const VertexState s = vertex_state(x);
    const std::vector<Dual> base = base_points(x, s);
    const std::vector<Dual> points = apply_stencils(surface_.tables().stencils, base);
    std::vector<SurfacePoint> found =
        closest_limit_points(surface_.tables().plans, points, targets_, options_.correspondence_level);
    std::vector<LimitWeights> weights(targets_.size());
    const long m = long(targets_.size());
#pragma omp parallel for schedule(dynamic, 256)
    for (long j = 0; j < m; ++j) {
      const SurfacePoint& c = found[size_t(j)];
      weights[size_t(j)] = limit_weights(surface_.tables().plans, surface_.tables().stencils, c.patch, c.u, c.v);
    }
    distances_.resize(found.size());
    for (size_t j = 0; j < found.size(); ++j) distances_[j] = found[j].distance;
    if (!correspondences_.empty()) {
      // The old point is kept where it is closer; with a normal term, where its distance and normal
      // residual together are smaller, so that the objective never rises as the points move.
      const std::vector<PointState> old = point_states(s, weights_);
      const std::vector<PointState> now = normal_scale_ > 0 ? point_states(s, weights) : std::vector<PointState>();
      for (size_t j = 0; j < found.size(); ++j) {
        const double old_distance = old[j].residual.norm();
        distances_[j] = std::min(distances_[j], old_distance);
        const bool keep =
            normal_scale_ > 0 ? point_energy(old[j]) < point_energy(now[j]) : old_distance < found[j].distance;
        if (keep) {
          found[j] = correspondences_[j];
          found[j].distance = old_distance;
          weights[j] = std::move(weights_[j]);
        } else if (normal_scale_ > 0) {
          found[j].distance = now[j].residual.norm();
        }
      }
    }
    correspondences_ = std::move(found);
    weights_ = std::move(weights);
    build_pattern();
  }

  // Each point's distance to the surface: to the closest point found, or its last one where nearer.
  const std::vector<double>& distances() const { return distances_; }

  DistanceSummary error() const { return summarise_distances(distances(), diagonal_); }

  // Squared distances at the present correspondences plus the smoothness term.
  double objective(const Parameters& x) const {
    const std::vector<PointState> points = point_states(vertex_state(x));
    double sum = 0;
    for (const auto& p : points) sum += p.residual.squaredNorm();
    return sum + normal_energy(points) + smoothness_energy(x) + prior_energy(x);
  }

  double objective_of_correspondences(const Parameters& x) const {
    double sum = 0;
    for (const auto& c : correspondences_) sum += c.distance * c.distance;
    if (normal_scale_ > 0) sum += normal_energy(point_states(vertex_state(x)));
    return sum + smoothness_energy(x) + prior_energy(x);
  }

  // The Gauss-Newton normal equations at `x`: H (lower triangle) and g, H δ = −g.
  void normal_equations(const Parameters& x, Eigen::SparseMatrix<double>& h, Eigen::VectorXd& g) const {
    const VertexState s = vertex_state(x);
    const std::vector<PointState> points = point_states(s);
    std::vector<std::vector<double>> rows(static_cast<size_t>(n_));  // per vertex: its blocks (i, k ≥ i), p × p each
    g = Eigen::VectorXd::Zero(unknowns());
    const int pp = p_ * p_;
#pragma omp parallel for schedule(dynamic, 16)
    for (int i = 0; i < n_; ++i) {
      std::vector<double>& row = rows[size_t(i)];
      row.assign(size_t(pattern_offsets_[size_t(i) + 1] - pattern_offsets_[size_t(i)]) * size_t(pp), 0.0);
      const int* cols = pattern_columns_.data() + pattern_offsets_[size_t(i)];
      const int n_cols = pattern_offsets_[size_t(i) + 1] - pattern_offsets_[size_t(i)];
      Eigen::Matrix<double, 9, 1> gi = Eigen::Matrix<double, 9, 1>::Zero();
      const bool normal = normal_scale_ > 0;
      for (int e = users_offsets_[size_t(i)]; e < users_offsets_[size_t(i) + 1]; ++e) {
        const int j = users_[size_t(e)].first, a = users_[size_t(e)].second;
        const LimitWeights& w = weights_[size_t(j)];
        const PointState& pt = points[size_t(j)];
        const PointJacobian ji = jacobian(s, x, pt, w, size_t(a));
        gi += ji.position.transpose() * pt.residual;
        if (normal) gi += ji.normal.transpose() * pt.normal_residual;
        for (size_t b = size_t(a); b < w.size(); ++b) {
          const int k = w.vertex[b];
          const PointJacobian jk = b == size_t(a) ? ji : jacobian(s, x, pt, w, b);
          const int slot = int(std::lower_bound(cols, cols + n_cols, k) - cols);
          if (p_ == 9) {
            Eigen::Map<Block> block(row.data() + size_t(slot) * size_t(pp));
            block.noalias() += ji.position.transpose() * jk.position;
            if (normal) block.noalias() += ji.normal.transpose() * jk.normal;
          } else {
            Eigen::Map<Eigen::Matrix3d> b3(row.data() + size_t(slot) * size_t(pp));
            b3.noalias() += ji.position.leftCols<3>().transpose() * jk.position.leftCols<3>();
            if (normal) b3.noalias() += ji.normal.leftCols<3>().transpose() * jk.normal.leftCols<3>();
          }
        }
      }
      g.segment(p_ * i, p_) = gi.head(p_);
    }
    std::vector<Eigen::Triplet<double>> entries;
    for (int i = 0; i < n_; ++i)
      for (int e = pattern_offsets_[size_t(i)]; e < pattern_offsets_[size_t(i) + 1]; ++e) {
        const int k = pattern_columns_[size_t(e)];
        const double* block = rows[size_t(i)].data() + size_t(e - pattern_offsets_[size_t(i)]) * size_t(pp);
        for (int c1 = 0; c1 < p_; ++c1)
          for (int c2 = 0; c2 < p_; ++c2) {
            const int row = p_ * k + c2, col = p_ * i + c1;  // block (i, k) transposed into the lower triangle
            if (row >= col) entries.emplace_back(row, col, block[c1 + p_ * c2]);
          }
      }
    // Smoothness: w · LᵀL on every component, the factors' weighted by the squared edge length.
    const Eigen::MatrixXd d = changes(x);
    for (int outer = 0; outer < laplacian_normal_.outerSize(); ++outer)
      for (Eigen::SparseMatrix<double>::InnerIterator it(laplacian_normal_, outer); it; ++it) {
        const int r = int(it.row()), c = int(it.col());
        for (int comp = 0; comp < p_; ++comp) {
          const double w = component_weight(comp) * it.value();
          if (r >= c) entries.emplace_back(p_ * r + comp, p_ * c + comp, w);
          g[p_ * r + comp] += w * d(c, comp);
        }
      }
    // The covariance prior: a diagonal term per factor parameter.
    for (size_t i = 0; i < prior_.size(); ++i)
      for (int c = 0; c < 6; ++c) {
        const int u = p_ * int(i) + 3 + c;
        const double w = prior_[i][c];
        entries.emplace_back(u, u, w);
        g[u] += w * (x.factors[i][c] - start_.factors[i][c]);
      }
    for (int u = 0; u < unknowns(); ++u) entries.emplace_back(u, u, 0.0);
    h.resize(unknowns(), unknowns());
    h.setFromTriplets(entries.begin(), entries.end());
  }

  Parameters stepped(const Parameters& x, const Eigen::VectorXd& delta) const {
    Parameters y = x;
    for (int i = 0; i < n_; ++i) {
      y.means[size_t(i)] += delta.segment<3>(p_ * i);
      if (p_ == 9) {
        y.factors[size_t(i)] += delta.segment<6>(p_ * i + 3);
        bound(i, y.factors[size_t(i)]);
      }
    }
    return y;
  }

  CovarianceMesh mesh_of(const CovarianceMesh& coarse, const Parameters& x) const {
    CovarianceMesh m = coarse;
    const VertexState s = vertex_state(x);
    for (int i = 0; i < n_; ++i) {
      m.set_mean(size_t(i), x.means[size_t(i)]);
      const Mat3 l_inverse = s.factor[size_t(i)].triangularView<Eigen::Lower>().solve(Mat3::Identity());
      m.set_covariance(size_t(i), p_ == 3 ? Mat3(plain_precision_.inverse()) : Mat3(l_inverse.transpose() * l_inverse));
    }
    return m;
  }

private:
  // The smoothness term's weight on a component: the means', or the factor parameters' times the squared edge length.
  double component_weight(int comp) const {
    return comp < 3 ? smoothness_ : covariance_smoothness_ * length_ * length_;
  }

  // Per vertex, per component: the change from the start (factor parameters scaled by the edge length).
  Eigen::MatrixXd changes(const Parameters& x) const {
    Eigen::MatrixXd d(n_, p_);
    for (int i = 0; i < n_; ++i) {
      d.block<1, 3>(i, 0) = (x.means[size_t(i)] - start_.means[size_t(i)]).transpose();
      if (p_ == 9) d.block<1, 6>(i, 3) = (x.factors[size_t(i)] - start_.factors[size_t(i)]).transpose();
    }
    return d;
  }

  // Per vertex i, the prior's weight on each factor parameter: w ℓᵢ² s_c², with ℓᵢ the mean length of
  // the vertex's edges and s_c what makes the parameter's change dimensionless (1 for a logarithmic
  // diagonal entry; for an entry below the diagonal, the start's diagonal entry of its column, that
  // entry's scale). Its energy is scale-invariant like the squared distances it is weighed against.
  void set_prior(double weight) {
    constexpr int kDiagonalParameter[3] = {0, 2, 5};
    prior_.assign(size_t(n_), Vec6::Zero());
    for (size_t i = 0; i < size_t(n_); ++i) {
      const double edge = edge_[i];
      for (int c = 0; c < 6; ++c) {
        const int a = kFactorEntries[c][0], b = kFactorEntries[c][1];
        const double scale = a == b ? 1.0 : std::exp(-start_.factors[i][kDiagonalParameter[b]]);
        prior_[i][c] = weight * edge * edge * scale * scale;
      }
    }
  }

  // Vertex i's factor parameters moved, where its standard deviations leave the bounds of
  // FitOptions::min_sigma and max_sigma, to those of the covariance with its eigenvalues clamped.
  void bound(int i, Vec6& factor) const {
    const Mat3 l = cholesky_factor(factor);
    const Mat3 l_inverse = l.triangularView<Eigen::Lower>().solve(Mat3::Identity());
    const Eigen::SelfAdjointEigenSolver<Mat3> eigen(l_inverse.transpose() * l_inverse);
    const double edge = edge_[size_t(i)];
    const double low = (relaxed_ ? options_.relaxed_min_sigma : options_.min_sigma) * edge,
                 high = options_.max_sigma * edge;
    const Vec3 variances = eigen.eigenvalues().cwiseMax(low * low).cwiseMin(high * high);
    if (variances == eigen.eigenvalues()) return;
    const Mat3& v = eigen.eigenvectors();
    factor = factor_parameters(v * variances.cwiseInverse().asDiagonal() * v.transpose());
  }

  double prior_energy(const Parameters& x) const {
    double sum = 0;
    for (size_t i = 0; i < prior_.size(); ++i) sum += prior_[i].dot((x.factors[i] - start_.factors[i]).cwiseAbs2());
    return sum;
  }

  // The normal term: every point's squared normal residual (the squared sine of the angle, scaled).
  static double normal_energy(const std::vector<PointState>& points) {
    double sum = 0;
    for (const auto& p : points) sum += p.normal_residual.squaredNorm();
    return sum;
  }

  double smoothness_energy(const Parameters& x) const {
    const Eigen::MatrixXd d = changes(x);
    double sum = 0;
    for (int comp = 0; comp < p_; ++comp)
      sum += component_weight(comp) * d.col(comp).dot(laplacian_normal_ * d.col(comp));
    return sum;
  }

  static double point_energy(const PointState& p) { return p.residual.squaredNorm() + p.normal_residual.squaredNorm(); }

  std::vector<PointState> point_states(const VertexState& s) const { return point_states(s, weights_); }

  std::vector<PointState> point_states(const VertexState& s, const std::vector<LimitWeights>& weights) const {
    std::vector<PointState> out(targets_.size());
    const long m = long(targets_.size());
    // The means as given by the state's precisions: h_k = K_k μ_k.
#pragma omp parallel for schedule(dynamic, 256)
    for (long j = 0; j < m; ++j) {
      const LimitWeights& w = weights[size_t(j)];
      Mat3 k = Mat3::Zero(), k_u = Mat3::Zero(), k_v = Mat3::Zero();
      Vec3 h = Vec3::Zero(), h_u = Vec3::Zero(), h_v = Vec3::Zero();
      for (size_t a = 0; a < w.size(); ++a) {
        const size_t i = size_t(w.vertex[a]);
        const Vec3 ki_mean = s.precision[i] * means_[i];
        k += w.value[a] * s.precision[i];
        h += w.value[a] * ki_mean;
        if (normal_scale_ > 0) {
          k_u += w.du[a] * s.precision[i];
          k_v += w.dv[a] * s.precision[i];
          h_u += w.du[a] * ki_mean;
          h_v += w.dv[a] * ki_mean;
        }
      }
      const Eigen::LLT<Mat3> llt(k);
      PointState& p = out[size_t(j)];
      p.inverse = llt.solve(Mat3::Identity());
      p.x = llt.solve(h);
      p.residual = p.x - targets_[size_t(j)];
      if (normal_scale_ > 0) {
        // x_u = K⁻¹ (h_u − K_u x); m = c/|c| with c = x_u × x_v; the residual ŝ (I − n nᵀ) m, whose
        // derivative by c is ŝ (I − n nᵀ)(I − m mᵀ)/|c|.
        p.precision_derivative[0] = k_u;
        p.precision_derivative[1] = k_v;
        p.tangent[0] = p.inverse * (h_u - k_u * p.x);
        p.tangent[1] = p.inverse * (h_v - k_v * p.x);
        const Vec3& n = normals_[size_t(j)];
        const Vec3 c = p.tangent[0].cross(p.tangent[1]);
        const double length = c.norm();
        if (length > 0 && !n.isZero()) {
          const Vec3 m = c / length;
          const Mat3 across = Mat3::Identity() - n * n.transpose();
          p.normal_residual = normal_scale_ * across * m;
          p.normal_gradient = normal_scale_ / length * across * (Mat3::Identity() - m * m.transpose());
        }
      }
    }
    return out;
  }

  // The derivatives at a point by the unknowns of its weights' vertex `a` (i, with weights w, w_u, w_v):
  // dx = w K⁻¹ B with B = [K_i | dK_i/dθ_c (μ_i − x)], and from x_u = K⁻¹ (h_u − K_u x),
  // dx_u = K⁻¹ (w_u B − K_u dx − w [0 | dK_i/dθ_c x_u]); likewise for v.
  PointJacobian jacobian(const VertexState& s, const Parameters& x, const PointState& pt, const LimitWeights& weights,
                         size_t a) const {
    const size_t i = size_t(weights.vertex[a]);
    const double w = weights.value[a];
    Eigen::Matrix<double, 3, 9> b = Eigen::Matrix<double, 3, 9>::Zero();
    b.leftCols<3>() = s.precision[i];
    if (p_ == 9) b.rightCols<6>() = precision_derivatives_times(s.factor[i], x.means[i] - pt.x);
    PointJacobian out;
    out.position = w * pt.inverse * b;
    out.normal.setZero();
    if (!(normal_scale_ > 0) || pt.normal_gradient.isZero()) return out;
    Eigen::Matrix<double, 3, 9> tangent[2];
    for (int d = 0; d < 2; ++d) {
      tangent[d] = (d == 0 ? weights.du[a] : weights.dv[a]) * b;
      tangent[d].noalias() -= pt.precision_derivative[d] * out.position;
      if (p_ == 9) tangent[d].rightCols<6>() -= w * precision_derivatives_times(s.factor[i], pt.tangent[d]);
      tangent[d] = pt.inverse * tangent[d];
    }
    // dc = dx_u × x_v + x_u × dx_v.
    out.normal =
        pt.normal_gradient * (cross_matrix(pt.tangent[0]) * tangent[1] - cross_matrix(pt.tangent[1]) * tangent[0]);
    return out;
  }

  // Which blocks (i, k ≥ i) the normal matrix has (vertices sharing a point), and per vertex the
  // points that read it with its position among their weights.
  void build_pattern() {
    users_offsets_.assign(size_t(n_) + 1, 0);
    for (const auto& w : weights_)
      for (const int i : w.vertex) ++users_offsets_[size_t(i) + 1];
    for (int i = 0; i < n_; ++i) users_offsets_[size_t(i) + 1] += users_offsets_[size_t(i)];
    users_.resize(size_t(users_offsets_.back()));
    std::vector<int> fill(users_offsets_.begin(), users_offsets_.end() - 1);
    for (size_t j = 0; j < weights_.size(); ++j)
      for (size_t a = 0; a < weights_[j].size(); ++a)
        users_[size_t(fill[size_t(weights_[j].vertex[a])]++)] = {int(j), int(a)};
    pattern_offsets_.assign(1, 0);
    pattern_columns_.clear();
    std::vector<int> stamp(size_t(n_), -1), row;
    for (int i = 0; i < n_; ++i) {
      row.assign(1, i);
      stamp[size_t(i)] = i;
      for (int e = users_offsets_[size_t(i)]; e < users_offsets_[size_t(i) + 1]; ++e) {
        const LimitWeights& w = weights_[size_t(users_[size_t(e)].first)];
        for (size_t b = size_t(users_[size_t(e)].second); b < w.size(); ++b)
          if (stamp[size_t(w.vertex[b])] != i) stamp[size_t(w.vertex[b])] = i, row.push_back(w.vertex[b]);
      }
      std::sort(row.begin(), row.end());
      pattern_columns_.insert(pattern_columns_.end(), row.begin(), row.end());
      pattern_offsets_.push_back(int(pattern_columns_.size()));
    }
  }

public:
  // The means the point states read: set before point_states (the parameters' means).
  void set_means(const Parameters& x) { means_ = x.means; }

private:
  const FitOptions& options_;
  bool relaxed_ = false;  // the lower bound at FitOptions::relaxed_min_sigma: the second stage
  const std::vector<Vec3>& targets_;
  const std::vector<Vec3>& normals_;
  PlannedSurface surface_;
  int n_, p_;
  Parameters start_;
  Mat3 plain_precision_;
  double diagonal_ = 1, length_ = 1, smoothness_ = 0, covariance_smoothness_ = 0;
  double normal_scale_ = 0;  // the normal residuals' length scale (0: no normal term)
  Eigen::SparseMatrix<double> laplacian_normal_;
  std::vector<double> edge_;  // per vertex, the mean length of its edges at the start
  std::vector<Vec6> prior_;   // per vertex, the covariance prior's weight on each factor parameter (empty: none)
  std::vector<SurfacePoint> correspondences_;
  std::vector<double> distances_;
  std::vector<LimitWeights> weights_;
  std::vector<int> users_offsets_, pattern_offsets_, pattern_columns_;
  std::vector<std::pair<int, int>> users_;
  std::vector<Vec3> means_;
};

}  // namespace

bool fits_in_two_stages(const FitOptions& options) {
  return !options.plain && options.relaxed_min_sigma < options.min_sigma;
}

CovarianceMesh with_isotropic_covariances(const CovarianceMesh& mesh) {
  double sum = 0;
  size_t count = 0;
  for (size_t e = 0; e < mesh.n_edges(); ++e) {
    const auto [low, high] = mesh.edge(e);
    sum += (mesh.mean(size_t(high)) - mesh.mean(size_t(low))).norm();
    ++count;
  }
  const double sigma = count > 0 && sum > 0 ? 0.5 * sum / double(count) : 1.0;
  CovarianceMesh out = mesh;
  for (size_t i = 0; i < out.n_vertices(); ++i) out.set_covariance(i, sigma * sigma * Mat3::Identity());
  return out;
}

const char* describe(FitStop stop) {
  switch (stop) {
    case FitStop::iterations:
      return "ran its iterations";
    case FitStop::converged:
      return "converged (the rms distance and the objective fell by less than the tolerance)";
    case FitStop::time:
      return "ran out of time";
    case FitStop::no_descent:
      return "no step lowered the error";
  }
  return "";
}

FitResult fit_limit_surface(const CovarianceMesh& coarse, const std::vector<Vec3>& targets, const FitOptions& options,
                            const std::vector<Vec3>& normals) {
  if (targets.empty()) throw Error("there are no points to fit the surface to");
  if (!normals.empty() && normals.size() != targets.size())
    throw Error("the fit has " + std::to_string(normals.size()) + " normals for " + std::to_string(targets.size()) +
                " points");
  if (!(options.normal_weight >= 0 && std::isfinite(options.normal_weight)))
    throw Error("the fit's normal weight must be a finite weight, 0 or more");
  if (coarse.n_faces() == 0) throw Error("the mesh to fit has no faces");
  if (!(options.tolerance >= 0 && options.tolerance <= 1))
    throw Error("the fit's tolerance must be a fraction from 0 to 1");
  if (!(options.time_budget > 0)) throw Error("the fit's time budget must be positive");
  if (!(options.min_sigma >= 0 && options.min_sigma < options.max_sigma))
    throw Error("the fit's standard deviation bounds must be 0 or more, the lower below the upper");
  if (!(options.relaxed_min_sigma >= 0 && std::isfinite(options.relaxed_min_sigma)))
    throw Error("the fit's relaxed lower bound on the standard deviations must be finite, 0 or more");
  if (options.covariance_smoothness &&
      !(*options.covariance_smoothness >= 0 && std::isfinite(*options.covariance_smoothness)))
    throw Error("the fit's covariance smoothness must be a finite weight, 0 or more");
  if (!(options.covariance_prior >= 0 && std::isfinite(options.covariance_prior)))
    throw Error("the fit's covariance prior must be a finite weight, 0 or more");
  validate_gaussians(coarse);
  refuse_points_apart(coarse, targets);
  const auto start = std::chrono::steady_clock::now();
  auto clock = start;
  FitProblem problem(coarse, targets, normals, options);
  Parameters x = problem.start();
  problem.set_means(x);
  problem.update_correspondences(x);
  FitResult result;
  double energy = problem.objective_of_correspondences(x);
  // A GPS fit moves its means alone first (FitOptions::means_first).
  bool means_only = problem.unknowns_per_vertex() == 9 && options.means_first > 0;
  const auto held = [&](int u) { return means_only && u % problem.unknowns_per_vertex() >= 3; };
  const auto report = [&](int iteration) {
    FitIteration it{iteration,  problem.error(),  seconds_since(clock), std::sqrt(energy / double(targets.size())),
                    means_only, problem.relaxed()};
    result.iterations.push_back(it);
    if (options.progress) options.progress(it);
    clock = std::chrono::steady_clock::now();
  };
  report(0);
  double damping = 1e-4;
  for (int iteration = 1; iteration <= options.iterations; ++iteration) {
    Eigen::SparseMatrix<double> h;
    Eigen::VectorXd g;
    problem.normal_equations(x, h, g);
    const Eigen::VectorXd diagonal = h.diagonal();
    const double floor = 1e-12 * std::max(diagonal.maxCoeff(), 1e-300);
    // Conjugate gradients (the damped system is positive definite): a direct factorisation's fill-in
    // grows too fast with the control vertices and the 9×9 blocks. The step is a truncated Newton
    // step: a hundred iterations give the direction that many more would, and the damping loop
    // below accepts only steps that lower the objective.
    Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower, BlockJacobiPreconditioner> solver;
    solver.preconditioner().set_block_size(problem.unknowns_per_vertex());
    solver.setTolerance(1e-6);
    solver.setMaxIterations(100);
    bool accepted = false;
    // Levenberg-Marquardt: H + λ diag(H), λ raised until a step lowers the objective.
    for (int attempt = 0; attempt < 12 && !accepted; ++attempt) {
      Eigen::SparseMatrix<double> damped = h;
      for (int u = 0; u < problem.unknowns(); ++u)
        damped.coeffRef(u, u) += damping * diagonal[u] + floor + (held(u) ? 1e30 : 0.0);
      solver.compute(damped);
      Eigen::VectorXd delta = -solver.solve(g);
      for (int u = 0; u < problem.unknowns(); ++u)
        if (held(u)) delta[u] = 0;
      {
        const Parameters y = problem.stepped(x, delta);
        problem.set_means(y);
        const double e = delta.allFinite() ? problem.objective(y) : INFINITY;
        if (e < energy) {
          x = y;
          accepted = true;
          damping = std::max(damping / 3, 1e-9);
          break;
        }
        problem.set_means(x);
      }
      damping *= 4;
    }
    if (!accepted && means_only) {
      means_only = false;  // no step of the means alone: this iteration again, the covariances free
      --iteration;
      continue;
    }
    if (!accepted && problem.relax_lower_bound()) {
      --iteration;  // no step within the first bound: this iteration again, at the relaxed one
      continue;
    }
    if (!accepted) {
      result.stop = FitStop::no_descent;
      break;
    }
    problem.update_correspondences(x);
    energy = problem.objective_of_correspondences(x);
    const FitIteration before = result.iterations.back();
    report(iteration);
    if (iteration == options.iterations) break;
    const FitIteration& now = result.iterations.back();
    if (means_only) {
      means_only = before.error.rms - now.error.rms > options.means_first * before.error.rms;
    } else if (options.tolerance > 0 && before.objective - now.objective <= options.tolerance * before.objective &&
               before.error.rms - now.error.rms <= options.tolerance * before.error.rms) {
      if (!problem.relax_lower_bound()) {  // else converged at the first bound: on at the relaxed one
        result.stop = FitStop::converged;
        break;
      }
    }
    if (seconds_since(start) >= options.time_budget) {
      result.stop = FitStop::time;
      break;
    }
  }
  result.mesh = problem.mesh_of(coarse, x);
  return result;
}

}  // namespace gps
