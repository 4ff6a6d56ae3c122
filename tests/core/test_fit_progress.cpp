// A fit's progress: the iterations' share, the time budget's, and with a tolerance how far the
// larger of the rms distance's and the objective's fall per iteration has shrunk toward it on a log
// scale, each of a two-stage fit's stages half of it; never back, never 1 before the end.
#include <gtest/gtest.h>

#include <cmath>

#include "core/fitting/fit_progress.h"

namespace gps {
namespace {

FitIteration iteration(int k, double rms, double seconds = 0.1, double objective = -1) {
  FitIteration it;
  it.iteration = k;
  it.error.rms = rms;
  it.seconds = seconds;
  it.objective = objective < 0 ? rms : objective;
  return it;
}

/// A fit that converges once: its bound on the standard deviations is never relaxed.
FitOptions one_stage() {
  FitOptions options;  // at most 100 iterations, tolerance 1 %
  options.relaxed_min_sigma = options.min_sigma;
  return options;
}

TEST(FitProgress, ConvergingFallsCountOnALogScaleTowardTheTolerance) {
  FitProgress progress(one_stage());
  EXPECT_EQ(progress.after(iteration(0, 1.0)), 0.0);
  // Falls of 10 %, then 5 %, 2.5 %, 1.25 %: log10(10 / fall) of the way from 10 % to 1 %.
  double rms = 0.9;
  EXPECT_NEAR(progress.after(iteration(1, rms)), 0.01, 1e-12);  // the iterations' share
  for (const double fall : {0.05, 0.025, 0.0125}) {
    rms *= 1 - fall;
    const int k = fall == 0.05 ? 2 : fall == 0.025 ? 3 : 4;
    EXPECT_NEAR(progress.after(iteration(k, rms)), std::log10(0.1 / fall), 1e-12) << fall;
  }
  // A fall under the tolerance: the fit stops now; the fraction stays below 1 until it returns.
  rms *= 1 - 0.005;
  EXPECT_EQ(progress.after(iteration(5, rms)), 0.99);
}

TEST(FitProgress, TwoStagesEachTakeHalfOfTheConvergence) {
  FitOptions options;  // the bound relaxed once the fit converges (FitOptions::relaxed_min_sigma)
  FitProgress progress(options);
  progress.after(iteration(0, 1.0));
  progress.after(iteration(1, 0.9));                                  // a fall of 10 %
  EXPECT_NEAR(progress.after(iteration(2, 0.9 * 0.99)), 0.5, 1e-12);  // converged at the first bound
  // The second stage measures from its own first fall, 10 % again, toward the tolerance.
  FitIteration relaxed = iteration(3, 0.9 * 0.99 * 0.9);
  relaxed.relaxed = true;
  EXPECT_NEAR(progress.after(relaxed), 0.5, 1e-12);
  relaxed = iteration(4, relaxed.error.rms * (1 - 0.05 / 2));
  relaxed.relaxed = true;
  EXPECT_NEAR(progress.after(relaxed), 0.5 + 0.5 * std::log10(0.1 / 0.025), 1e-12);
  // A plain fit has one stage whatever the bounds.
  options.plain = true;
  FitProgress plain(options);
  plain.after(iteration(0, 1.0));
  plain.after(iteration(1, 0.9));
  EXPECT_NEAR(plain.after(iteration(2, 0.9 * 0.95)), std::log10(2.0), 1e-12);
}

TEST(FitProgress, TheLargerOfTheTwoFallsCounts) {
  FitProgress progress(one_stage());
  progress.after(iteration(0, 1.0, 0.1, 2.0));
  EXPECT_NEAR(progress.after(iteration(1, 0.9, 0.1, 1.0)), 0.01, 1e-12);  // falls of 10 % and 50 %: the first
  // The rms rises while the objective falls by 5 % of the 50 % fall: log10(50 / 5) / log10(50 / 1).
  EXPECT_NEAR(progress.after(iteration(2, 0.95, 0.1, 0.95)), 1 / std::log10(50.0), 1e-12);
}

TEST(FitProgress, IterationsAndTimeWithoutToleranceAndNeverBack) {
  FitOptions options;
  options.iterations = 4;
  options.tolerance = 0;
  options.time_budget = 1.0;
  FitProgress progress(options);
  progress.after(iteration(0, 1.0, 0.0));
  EXPECT_DOUBLE_EQ(progress.after(iteration(1, 0.5, 0.6)), 0.6);     // the time budget's share
  EXPECT_DOUBLE_EQ(progress.after(iteration(2, 0.4, 0.01)), 0.61);   // 0.61 s against 2 of 4 iterations
  EXPECT_DOUBLE_EQ(progress.after(iteration(3, 0.45, 0.01)), 0.75);  // an rms that rose does not count
  EXPECT_DOUBLE_EQ(progress.after(iteration(4, 0.3, 0.0)), 0.99);
}

}  // namespace
}  // namespace gps
