#pragma once
// A progress bar on stderr for gpsurf's long commands: one line redrawn in place with '\r' (at most
// ten times a second) giving the stage, the percent done and the seconds spent, ended by a newline.
// Nothing at all is written where stderr is not a terminal (a pipe, a file, a test) or under --quiet.
#include <chrono>
#include <functional>
#include <iosfwd>
#include <string>

#include "core/support/progress.h"

namespace gps {

class TerminalProgress {
public:
  using Clock = std::function<double()>;  // seconds since some fixed moment

  /// A bar for `stage` ("simplifying") on stderr, shown when stderr is a terminal and not `quiet`.
  TerminalProgress(std::string stage, bool quiet);
  /// A bar written to `out` where `shown`, timed by `clock` (for tests).
  TerminalProgress(std::string stage, std::ostream& out, bool shown, Clock clock);
  /// Ends the line where a bar was drawn (at the percent reached: the work failed if it was not done).
  ~TerminalProgress();
  TerminalProgress(const TerminalProgress&) = delete;
  TerminalProgress& operator=(const TerminalProgress&) = delete;

  /// Records the fraction done (0 to 1), redrawing the bar where a tenth of a second has passed
  /// since it was last drawn.
  void update(double fraction);
  /// A core ProgressReport that updates this bar and never asks the work to stop.
  ProgressReport report();
  /// Blanks the bar's line, for a line of other output to take its place (a terminal shows stdout and
  /// stderr together); the next update draws the bar again at once.
  void clear();
  /// Draws the bar at 100% and ends its line; later calls do nothing.
  void finish();

private:
  void draw(double fraction);

  std::string stage_;
  std::ostream& out_;
  bool shown_;
  Clock clock_;
  double start_, last_drawn_ = -1;  // seconds by clock_; −1: not drawn yet (or cleared)
  size_t drawn_width_ = 0;           // of the line last drawn
  bool finished_ = false;
};

}  // namespace gps
