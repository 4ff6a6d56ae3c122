#pragma once
// Lists of integers in compressed rows (list r holds values[offsets[r] .. offsets[r+1])): their
// transpose, and the sorted union of some of them. The stencil dependents (which rows read a base
// vertex) and the patch readers (which patches read a plan point) are both such transposes.
#include <algorithm>
#include <vector>

namespace gps {

/// Per column c < n_columns, the lists that hold c, in increasing order (a counting sort).
inline void transpose_lists(const std::vector<int>& offsets, const std::vector<int>& values, int n_columns,
                            std::vector<int>& out_offsets, std::vector<int>& out_values) {
  out_offsets.assign(size_t(n_columns) + 1, 0);
  for (const int c : values) ++out_offsets[size_t(c) + 1];
  for (size_t c = 0; c < size_t(n_columns); ++c) out_offsets[c + 1] += out_offsets[c];
  out_values.resize(values.size());
  std::vector<int> next(out_offsets.begin(), out_offsets.end() - 1);
  for (size_t r = 0; r + 1 < offsets.size(); ++r)
    for (int i = offsets[r]; i < offsets[r + 1]; ++i) out_values[size_t(next[size_t(values[size_t(i)])]++)] = int(r);
}

/// The values of lists `lists`, sorted, without repeats.
inline std::vector<int> union_of_lists(const std::vector<int>& offsets, const std::vector<int>& values,
                                       const std::vector<int>& lists) {
  std::vector<int> out;
  for (const int r : lists)
    out.insert(out.end(), values.begin() + offsets[size_t(r)], values.begin() + offsets[size_t(r) + 1]);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace gps
