#pragma once
// A stencil: a point as a sparse linear combination Σ w_k · q_{i_k} of base vertices (Far's
// stencils in OpenSubdiv's terms), the form in which plan points enter the stencil table.
#include <utility>
#include <vector>

namespace gps {

class Stencil {
public:
  Stencil() = default;
  /// The base vertex `index` itself (weight 1).
  static Stencil vertex(int index) {
    Stencil s;
    s.terms_.emplace_back(index, 1.0);
    return s;
  }
  /// A stencil from terms sorted by index without repeats.
  static Stencil from_terms(std::vector<std::pair<int, double>> terms) {
    Stencil s;
    s.terms_ = std::move(terms);
    return s;
  }

  const std::vector<std::pair<int, double>>& terms() const { return terms_; }
  bool empty() const { return terms_.empty(); }
  /// Sum of the weights (1 for every affine combination).
  double weight_sum() const;
  /// The single base vertex this stencil is, or −1.
  int as_vertex() const { return terms_.size() == 1 && terms_[0].second == 1.0 ? terms_[0].first : -1; }

  Stencil& operator+=(const Stencil& other);
  Stencil& operator*=(double s);
  friend Stencil operator+(Stencil a, const Stencil& b) { return a += b; }
  friend Stencil operator-(Stencil a, const Stencil& b) { return a += b * -1.0; }
  friend Stencil operator*(Stencil a, double s) { return a *= s; }
  friend Stencil operator*(double s, Stencil a) { return a *= s; }
  friend Stencil operator/(Stencil a, double s) { return a *= 1.0 / s; }

private:
  std::vector<std::pair<int, double>> terms_;  // sorted by index, no repeats
};

}  // namespace gps
