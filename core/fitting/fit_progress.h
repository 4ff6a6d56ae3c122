#pragma once
// How far a fit has come, for progress bars: it stops at its iterations' cap, its time budget or once
// converged, whichever comes first, so the iterations alone say little when it converges early.
#include "core/fitting/limit_fit.h"

namespace gps {

class FitProgress {
public:
  explicit FitProgress(const FitOptions& options)
      : iterations_(options.iterations),
        time_budget_(options.time_budget),
        tolerance_(options.tolerance),
        stages_(fits_in_two_stages(options) ? 2 : 1) {}
  /// The fraction done, 0 to below 1, after iteration `it` (given in order, iteration 0 first): the
  /// largest of the iterations run over the cap, the seconds spent over the time budget and, with a
  /// tolerance, how far the fall per iteration (the larger of the rms distance's and the
  /// objective's) has shrunk toward it. The falls shrink about geometrically as a fit converges, so
  /// that share is measured on a log scale, from the first iteration's fall down to the tolerance;
  /// a fit that converges twice (FitOptions::relaxed_min_sigma) has each stage take half of it.
  double after(const FitIteration& it);

private:
  int iterations_;
  double time_budget_, tolerance_;
  int stages_, stage_ = 0;
  double seconds_ = 0, last_rms_ = -1, last_objective_ = -1, first_fall_ = -1;
  double fraction_ = 0;
};

}  // namespace gps
