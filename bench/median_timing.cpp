#include "bench/median_timing.h"

#include <chrono>

#include "core/support/median.h"

namespace gps {

std::vector<double> interleaved_median_seconds(const std::vector<std::function<void()>>& functions, double budget) {
  using Clock = std::chrono::steady_clock;
  std::vector<std::vector<double>> times(functions.size());
  const auto start = Clock::now();
  for (size_t round = 0;
       round < 3 || (round < 200 && std::chrono::duration<double>(Clock::now() - start).count() < budget); ++round)
    for (size_t i = 0; i < functions.size(); ++i) {
      const auto t0 = Clock::now();
      functions[i]();
      times[i].push_back(std::chrono::duration<double>(Clock::now() - t0).count());
    }
  std::vector<double> medians;
  for (auto& t : times) medians.push_back(median(std::move(t)));
  return medians;
}

double median_seconds(const std::function<void()>& f, double budget) {
  return interleaved_median_seconds({f}, budget)[0];
}

}  // namespace gps
