#pragma once
// Which parts of a table a buffer that holds its previous version is sent again
// (render/pipeline/plan_buffers.h): the runs [begin, end) of elements, found by comparing the two, or
// from the records a change lists as written.
#include <algorithm>
#include <cstddef>
#include <cstring>
#include <utility>
#include <vector>

namespace gps {

/// The runs [begin, end) of elements of `data` that differ from `held` bit for bit (a weight of −0 is not
/// +0's), compared a chunk at a time (a chunk that differs is one run, joined to the one before where they
/// touch), and the elements past held's end. An operation changes the tables in a few places: the rest of
/// them is neither sent again nor, on a GPU, carried over the bus. The first `same` elements are known
/// to be held's: not compared.
template <class T>
std::vector<std::pair<size_t, size_t>> differing_runs(const std::vector<T>& data, const std::vector<T>& held,
                                                      size_t same = 0) {
  constexpr size_t kChunk = 4096;
  const size_t n = std::min(data.size(), held.size()), first = std::min(same, n);
  std::vector<std::pair<size_t, size_t>> runs;
  const auto add = [&](size_t begin, size_t end) {
    if (!runs.empty() && runs.back().second == begin)
      runs.back().second = end;
    else
      runs.emplace_back(begin, end);
  };
  const long long n_chunks = (long long)((n - first + kChunk - 1) / kChunk);
  std::vector<char> differs(size_t(n_chunks), 0);
#pragma omp parallel for schedule(static) if (n_chunks >= 64)
  for (long long c = 0; c < n_chunks; ++c) {
    const size_t begin = first + size_t(c) * kChunk, end = std::min(n, begin + kChunk);
    differs[size_t(c)] = std::memcmp(data.data() + begin, held.data() + begin, (end - begin) * sizeof(T)) != 0;
  }
  for (size_t c = 0; c < differs.size(); ++c)
    if (differs[c]) add(first + c * kChunk, std::min(n, first + (c + 1) * kChunk));
  if (data.size() > n) add(n, data.size());
  return runs;
}

/// The runs [begin, end) of the records of `stride` elements that `listed` names (ascending) in `size`
/// elements, and the elements past `held_size`, joined where they touch.
std::vector<std::pair<size_t, size_t>> listed_runs(const std::vector<int>& listed, size_t stride, size_t held_size,
                                                   size_t size);

}  // namespace gps
