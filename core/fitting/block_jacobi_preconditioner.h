#pragma once
// A block-Jacobi preconditioner for Eigen's ConjugateGradient: the inverse of each diagonal block
// of a fixed size (one vertex's unknowns in the fit: its mean and its precision's factor, whose
// scales differ by orders of magnitude, so that a diagonal preconditioner leaves the system badly
// conditioned within each block).
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace gps {

class BlockJacobiPreconditioner {
public:
  using Scalar = double;
  using StorageIndex = int;

  BlockJacobiPreconditioner() = default;

  /// The size of the diagonal blocks (the matrix's size must be a multiple of it); set before compute.
  void set_block_size(int size) { block_ = size; }

  Eigen::Index rows() const { return size_; }
  Eigen::Index cols() const { return size_; }

  template <typename Matrix>
  BlockJacobiPreconditioner& analyzePattern(const Matrix&) {
    return *this;
  }

  /// Factorises the diagonal blocks of `matrix`, read from its lower triangle (the conjugate
  /// gradients' Lower storage) and mirrored.
  template <typename Matrix>
  BlockJacobiPreconditioner& factorize(const Matrix& matrix) {
    size_ = matrix.rows();
    const int blocks = int(size_ / block_);
    factors_.clear();
    factors_.reserve(size_t(blocks));
    Eigen::MatrixXd block(block_, block_);
    for (int b = 0; b < blocks; ++b) {
      block.setZero();
      for (int c = 0; c < block_; ++c)
        for (typename Matrix::InnerIterator it(matrix, b * block_ + c); it; ++it) {
          const Eigen::Index r = it.row() - Eigen::Index(b) * block_;
          if (r < c || r >= block_) continue;
          block(r, c) = block(c, r) = it.value();
        }
      factors_.emplace_back(block);
    }
    return *this;
  }

  template <typename Matrix>
  BlockJacobiPreconditioner& compute(const Matrix& matrix) {
    return factorize(matrix);
  }

  /// z = blockdiag(A)⁻¹ r.
  template <typename Rhs>
  Eigen::VectorXd solve(const Eigen::MatrixBase<Rhs>& r) const {
    Eigen::VectorXd z(r.size());
    for (size_t b = 0; b < factors_.size(); ++b)
      z.segment(Eigen::Index(b) * block_, block_) = factors_[b].solve(r.segment(Eigen::Index(b) * block_, block_));
    return z;
  }

  Eigen::ComputationInfo info() const { return Eigen::Success; }

private:
  int block_ = 1;
  Eigen::Index size_ = 0;
  std::vector<Eigen::LDLT<Eigen::MatrixXd>> factors_;
};

}  // namespace gps
