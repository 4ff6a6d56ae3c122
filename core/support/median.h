#pragma once
// The median of a sample (timings in benchmarks and the editor's statistics).
#include <algorithm>
#include <vector>

namespace gps {

/// The upper median (element n/2 in sorted order) of `values`; 0 for none.
inline double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::nth_element(values.begin(), values.begin() + long(values.size() / 2), values.end());
  return values[values.size() / 2];
}

}  // namespace gps
