#include "render/pipeline/upload_runs.h"

namespace gps {

std::vector<std::pair<size_t, size_t>> listed_runs(const std::vector<int>& listed, size_t stride, size_t held_size,
                                                   size_t size) {
  std::vector<std::pair<size_t, size_t>> runs;
  const auto add = [&](size_t begin, size_t end) {
    end = std::min(end, size);
    if (begin >= end) return;
    if (!runs.empty() && runs.back().second >= begin)
      runs.back().second = std::max(runs.back().second, end);
    else
      runs.emplace_back(begin, end);
  };
  for (const int record : listed) add(size_t(record) * stride, size_t(record + 1) * stride);
  add(held_size, size);
  return runs;
}

}  // namespace gps
