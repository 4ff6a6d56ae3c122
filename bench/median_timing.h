#pragma once
// Wall-clock medians for the figures of `gpsurf bench` (bench/*_figures.h): each function timed over
// rounds that fill a time budget, so that a changing machine load hits every figure alike.
#include <functional>
#include <vector>

namespace gps {

/// Median seconds of each function over rounds that fill about `budget` seconds (at least 3, at most
/// 200); each round runs every function once, in order.
std::vector<double> interleaved_median_seconds(const std::vector<std::function<void()>>& functions, double budget);

/// Median seconds of `f` over repeats that fill about `budget` seconds (at least 3, at most 200).
double median_seconds(const std::function<void()>& f, double budget = 0.3);

}  // namespace gps
