#include "core/patches/stencil.h"

#include <cstddef>

namespace gps {

double Stencil::weight_sum() const {
  double sum = 0;
  for (const auto& t : terms_) sum += t.second;
  return sum;
}

Stencil& Stencil::operator+=(const Stencil& other) {
  if (other.terms_.empty()) return *this;
  std::vector<std::pair<int, double>> merged;
  merged.reserve(terms_.size() + other.terms_.size());
  std::size_t i = 0, j = 0;
  while (i < terms_.size() || j < other.terms_.size()) {
    if (j == other.terms_.size() || (i < terms_.size() && terms_[i].first < other.terms_[j].first)) {
      merged.push_back(terms_[i++]);
    } else if (i == terms_.size() || other.terms_[j].first < terms_[i].first) {
      merged.push_back(other.terms_[j++]);
    } else {
      merged.emplace_back(terms_[i].first, terms_[i].second + other.terms_[j].second);
      ++i, ++j;
    }
  }
  terms_ = std::move(merged);
  return *this;
}

Stencil& Stencil::operator*=(double s) {
  for (auto& t : terms_) t.second *= s;
  return *this;
}

}  // namespace gps
