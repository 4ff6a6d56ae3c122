#include "core/fitting/fit_progress.h"

#include <algorithm>
#include <cmath>

namespace gps {

double FitProgress::after(const FitIteration& it) {
  seconds_ += it.seconds;
  double fraction = iterations_ > 0 ? double(it.iteration) / iterations_ : 1.0;
  if (std::isfinite(time_budget_)) fraction = std::max(fraction, seconds_ / time_budget_);
  // The fit waits on the larger of the two falls (FitOptions::tolerance).
  const double fall = std::max(last_rms_ > 0 ? (last_rms_ - it.error.rms) / last_rms_ : 0.0,
                               last_objective_ > 0 ? (last_objective_ - it.objective) / last_objective_ : 0.0);
  if (it.relaxed && stage_ == 0) {
    stage_ = 1;  // the second stage measures its falls from its own first one
    first_fall_ = -1;
  }
  if (tolerance_ > 0 && fall > 0) {
    if (first_fall_ < 0) first_fall_ = fall;
    if (first_fall_ > tolerance_) {
      const double converged = std::log(first_fall_ / std::max(fall, tolerance_)) / std::log(first_fall_ / tolerance_);
      fraction = std::max(fraction, (std::min(stage_, stages_ - 1) + converged) / stages_);
    }
  }
  last_rms_ = it.error.rms;
  last_objective_ = it.objective;
  // Never back, and 1 only once the fit has returned.
  fraction_ = std::max(fraction_, std::min(fraction, 0.99));
  return fraction_;
}

}  // namespace gps
