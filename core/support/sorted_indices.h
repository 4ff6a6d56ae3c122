#pragma once
// Index lists sorted with their repeats dropped, as the incremental passes gather them (the patches or
// corner slots a change reaches, each listed once per neighbour that names it).
#include <algorithm>
#include <vector>

namespace gps {

/// Sorts `indices` (each in [0, end)) and drops repeats. Where they are many against `end` (a change
/// across the mesh), by a flag per index and one pass over the flags, which costs less than sorting
/// them; else by sorting.
inline void sort_unique_indices(std::vector<int>& indices, int end) {
  if (indices.size() * 8 < size_t(end)) {
    std::sort(indices.begin(), indices.end());
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
    return;
  }
  std::vector<char> listed(size_t(end), 0);
  for (const int i : indices) listed[size_t(i)] = 1;
  indices.clear();
  for (int i = 0; i < end; ++i)
    if (listed[size_t(i)]) indices.push_back(i);
}

}  // namespace gps
